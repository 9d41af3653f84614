#pragma once
// The anisotropic Voronoi diagram of sites that all share one metric M (a constant field). With
// M = FᵀF, d_v(p) = |F(p − v)| (LS §3), so the diagram is the ordinary Voronoi diagram of the
// mapped sites, pulled back: its cells are convex and hold their sites, it has no orphans, and
// every loose diagram of the sites is this diagram (LS §7). It is kept as its dual Del_M (LU
// Definition 2.1) by Bowyer–Watson insertion with the exact in-circle predicate in M; its Voronoi
// vertices are the M-circumcentres of the triangles, rational points.
//
// Three ghost sites far outside the sites' box, farther the more anisotropic M is, close the
// triangulation. No ghost lies in the M-circumdisc of a triangle of sites whose Voronoi vertex is
// in the box, so those triangles are exactly Del_M's; a triangle with a ghost is dual to a vertex
// whose disc would hold every site of the box, so it is no vertex in the box.
#include "numbers/expansion.hpp"
#include "numbers/filter_interval.hpp"
#include "numbers/rational.hpp"
#include "predicates/point.hpp"
#include "refiners/common/domain.hpp"

#include <array>
#include <vector>

namespace anisocert::refiners::ls {

using predicates::Point2;
using predicates::Sym2;

// The M-circumcentre p of a, b, c (not collinear): 2 (b − a)ᵀM (p − a) = |b − a|²_M and likewise
// for c, solved by Cramer's rule: p − a = (nx, ny) / det, polynomials in the inputs.
template <class T>
struct CircumcentreParts {
  T nx, ny, det;
};
template <class T>
CircumcentreParts<T> circumcentre_parts(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const T m11(M.m11), m12(M.m12), m22(M.m22), ax(a.x), ay(a.y);
  const T ux = T(b.x) - ax, uy = T(b.y) - ay, wx = T(c.x) - ax, wy = T(c.y) - ay;
  // Rows M u and M w; right-hand sides |u|²_M / 2 and |w|²_M / 2.
  const T r11 = m11 * ux + m12 * uy, r12 = m12 * ux + m22 * uy, r21 = m11 * wx + m12 * wy, r22 = m12 * wx + m22 * wy;
  const T U = (r11 * ux + r12 * uy) * T(0.5), W = (r21 * wx + r22 * wy) * T(0.5);
  return {U * r22 - W * r12, r11 * W - r21 * U, r11 * r22 - r12 * r21};
}
// The circumcentre in T: exactly (Rational), or a box holding it (FilterInterval; unbounded when
// the filter cannot tell the determinant from 0).
template <class T>
Point2<T> circumcentre_in(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const CircumcentreParts<T> p = circumcentre_parts<T>(a, b, c, M);
  return {T(a.x) + p.nx / p.det, T(a.y) + p.ny / p.det};
}
// The circumcentre rounded to the nearest doubles (Boost's conversion of the rational
// circumcentre), from its parts in expansions (numbers/expansion.hpp), and in rationals only when
// those cannot decide.
Point2<double> rounded_circumcentre(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M);

class DelaunayInMetric {
 public:
  // Counter-clockwise; across[i] is the triangle across the edge opposite v[i]. Ghosts have
  // negative ids.
  struct Triangle {
    std::array<int, 3> v;
    std::array<int, 3> across;
    bool alive = true;
  };

  // Sites are to lie in `extent` (the ghosts are 2¹⁰ of its size away).
  DelaunayInMetric(const Sym2<double>& M, const common::Box& extent);

  // Inserts site `id` at p (p in the extent box, distinct from every site, ids 0, 1, 2, … in
  // order); returns the triangles created (valid until the next insertion).
  const std::vector<int>& insert(int id, const Point2<double>& p);

  const Sym2<double>& metric() const { return M_; }
  const Triangle& triangle(int t) const { return triangles_[t]; }
  std::size_t slots() const { return triangles_.size(); }
  // No ghost among its vertices.
  bool real(int t) const;
  const Point2<double>& point(int id) const { return id >= 0 ? points_[id] : ghosts_[-id - 1]; }
  // The Voronoi vertex dual to triangle t: its circumcentre in M (circumcentre_in).
  template <class T>
  Point2<T> circumcentre(int t) const {
    const auto& v = triangles_[t].v;
    return circumcentre_in<T>(point(v[0]), point(v[1]), point(v[2]), M_);
  }
  // A box holding it (circumcentre<FilterInterval>), computed once per triangle.
  const Point2<FilterInterval>& circumcentre_box(int t) const {
    const auto k = static_cast<std::size_t>(t);
    if (!has_box_[k]) box_[k] = circumcentre<FilterInterval>(t), has_box_[k] = true;
    return box_[k];
  }

 private:
  int locate(const Point2<double>& p) const;
  int new_triangle(const std::array<int, 3>& v);

  Sym2<double> M_;
  std::array<Point2<double>, 3> ghosts_;
  std::vector<Point2<double>> points_;
  std::vector<Triangle> triangles_;
  mutable std::vector<Point2<FilterInterval>> box_;  // per slot, while has_box_
  mutable std::vector<bool> has_box_;
  std::vector<int> free_;  // dead slots, reused
  int recent_ = 0;         // a live triangle near the last insertion: where the next walk starts
  std::vector<int> created_, cavity_;
  std::vector<unsigned> stamp_;  // per triangle: marked inside or outside the cavity at insertion generation_
  unsigned generation_ = 0;
  std::vector<std::pair<int, int>> rim_;  // (cavity triangle, edge) on the cavity's boundary
};

}  // namespace anisocert::refiners::ls
