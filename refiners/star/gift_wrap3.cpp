#include "refiners/star/gift_wrap3.hpp"

#include "predicates/insphere_perturbed.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace anisocert::refiners::star {
namespace {

using predicates::Point3;
using predicates::Sym3;

class Wrap {
 public:
  Wrap(int v, const std::vector<int>& cand, const std::vector<Point3<double>>& p, const Sym3<double>& M) : v_(v), cand_(cand), p_(p), M_(M) {}

  Sign orientation(int a, int b, int c, int d) const { return predicates::orientation3(at(a), at(b), at(c), at(d)); }
  // Whether e is strictly inside the (perturbed) M-sphere of the positively oriented (v, a, b, c).
  bool inside(int a, int b, int c, int e) const {
    return predicates::insphere_perturbed<double>({at(v_), at(a), at(b), at(c), at(e)}, {v_, a, b, c, e}, M_) == Sign::positive;
  }
  bool empty(int a, int b, int c) const {
    return std::none_of(cand_.begin(), cand_.end(), [&](int e) { return e != a && e != b && e != c && inside(a, b, c, e); });
  }

  // A tetrahedron (v, a, b, c) of the star, positively oriented, or nothing (coplanar sites): a
  // the nearest candidate (va is a Delaunay edge); for b in order, the tetrahedra across the
  // triangle vab on either side (beyond), the first one empty of every candidate. When vab is a
  // Delaunay triangle, the tetrahedron beyond it on a side with candidates is Delaunay, so the
  // search ends at the first b that makes one (O(k) predicates per b).
  std::optional<std::array<int, 3>> first(const std::vector<int>& order) const {
    // (The order is by distances in doubles: should rounding put a non-neighbour first, the next
    // candidates are tried as a.)
    for (std::size_t i = 0; i < order.size(); ++i) {
      const int a = order[i];
      for (std::size_t j = 0; j < order.size(); ++j) {
        const int b = order[j];
        if (j == i) continue;
        if (const int d = beyond(a, b); d >= 0 && empty(b, a, d)) return std::array<int, 3>{b, a, d};
        if (const int d = beyond(b, a); d >= 0 && empty(a, b, d)) return std::array<int, 3>{a, b, d};
      }
    }
    return std::nullopt;
  }

  // The candidate d beyond the face (v, a, b) from c, with (v, b, a, d) empty; −1 when none.
  int beyond(int a, int b) const {
    int best = -1;
    for (const int e : cand_) {
      if (e == a || e == b || orientation(v_, b, a, e) != Sign::positive) continue;
      if (best < 0 || inside(b, a, best, e)) best = e;
    }
    return best;
  }

 private:
  const Point3<double>& at(int i) const { return p_[static_cast<std::size_t>(i)]; }
  int v_;
  const std::vector<int>& cand_;
  const std::vector<Point3<double>>& p_;
  const Sym3<double>& M_;
};

}  // namespace

Star3 gift_wrap_star3(int v, const std::vector<int>& candidates, const std::vector<Point3<double>>& points, const Sym3<double>& M) {
  // Candidates by approximate M-distance: the first tetrahedron is searched among the nearest, and
  // a candidate inside a tried sphere is found sooner among them (the order decides nothing).
  std::vector<std::pair<double, int>> by_distance;
  const auto& pv = points[static_cast<std::size_t>(v)];
  for (const int c : candidates) {
    const auto& q = points[static_cast<std::size_t>(c)];
    by_distance.emplace_back(predicates::quadratic_form(M, q.x - pv.x, q.y - pv.y, q.z - pv.z), c);
  }
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<int> order;
  for (const auto& [d, c] : by_distance) order.push_back(c);
  const Wrap w(v, order, points, M);
  Star3 star;
  const auto start = w.first(order);
  if (!start) return star;
  // Each directed link edge (a, b) once: the tetrahedron (v, a, b, c) has its faces (v, a, b),
  // (v, b, c), (v, c, a) with the link triangle (a, b, c) on their positive side.
  std::set<std::pair<int, int>> seen;  // directed link edges of the triangles found
  std::vector<std::array<int, 3>> todo{*start};
  seen.insert({{(*start)[0], (*start)[1]}, {(*start)[1], (*start)[2]}, {(*start)[2], (*start)[0]}});
  while (!todo.empty()) {
    const std::array<int, 3> t = todo.back();
    todo.pop_back();
    star.link.push_back(t);
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (seen.count({b, a})) continue;  // the neighbour across (v, a, b) is known
      const int d = w.beyond(a, b);
      if (d < 0) {
        star.open.push_back({a, b});
        continue;
      }
      const std::array<int, 3> u{b, a, d};
      seen.insert({{b, a}, {a, d}, {d, b}});
      todo.push_back(u);
    }
  }
  return star;
}

}  // namespace anisocert::refiners::star
