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
#include "refiners/common/circumcentre.hpp"
#include "refiners/common/domain.hpp"

#include <array>
#include <optional>
#include <vector>

namespace anisocert::refiners::ls {

using predicates::Point2;
using predicates::Sym2;

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
    return common::circumcentre_in<T>(point(v[0]), point(v[1]), point(v[2]), M_);
  }
  // A box holding it (common::circumcentre_box), computed once per triangle.
  const Point2<FilterInterval>& circumcentre_box(int t) const {
    auto& box = box_[static_cast<std::size_t>(t)];
    if (!box) {
      const auto& v = triangles_[t].v;
      box = common::circumcentre_box(point(v[0]), point(v[1]), point(v[2]), M_);
    }
    return *box;
  }
  // It exactly, by the fastest exact path (exact_circumcentre).
  Point2<Rational> exact_circumcentre(int t) const {
    const auto& v = triangles_[t].v;
    return common::exact_circumcentre(point(v[0]), point(v[1]), point(v[2]), M_);
  }
  // It rounded to the nearest doubles (rounded_circumcentre).
  Point2<double> rounded_circumcentre(int t) const {
    const auto& v = triangles_[t].v;
    return common::rounded_circumcentre(point(v[0]), point(v[1]), point(v[2]), M_);
  }

 private:
  int locate(const Point2<double>& p) const;
  int new_triangle(const std::array<int, 3>& v);

  Sym2<double> M_;
  std::array<Point2<double>, 3> ghosts_;
  std::vector<Point2<double>> points_;
  std::vector<Triangle> triangles_;
  mutable std::vector<std::optional<Point2<FilterInterval>>> box_;  // per slot, once asked for
  std::vector<int> free_;  // dead slots, reused
  int recent_ = 0;         // a live triangle near the last insertion: where the next walk starts
  std::vector<int> created_, cavity_;
  std::vector<unsigned> stamp_;  // per triangle: marked inside or outside the cavity at insertion generation_
  unsigned generation_ = 0;
  std::vector<std::pair<int, int>> rim_;  // (cavity triangle, edge) on the cavity's boundary
};

}  // namespace anisocert::refiners::ls
