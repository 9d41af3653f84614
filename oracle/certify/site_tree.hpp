#pragma once
// The mesh's sites in a static k-d tree (median splits, leaves of at most 8), for the certifier's
// box queries (the sites that may lie in a circumellipse, or on a segment): it adapts to clustered
// sites, where a uniform grid would scan crowded cells. It only selects candidates; every decision
// on them is an exact predicate. The coordinates are approximations of the sites (EnclosedMesh::approx), within one
// ulp of the exact ones, so every query box is widened by two ulps on each side before it is
// compared with them.
#include "predicates/point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace anisocert::oracle {

class SiteTree {
 public:
  explicit SiteTree(const std::vector<predicates::Point2<double>>& p) : p_(p), order_(p.size()) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    build(0, order_.size(), 0);
  }
  // Calls f(site) for the sites in the box (and possibly a few just outside it) until f returns
  // false (f may also return void: every site is visited).
  template <class F>
  void visit(double x0, double x1, double y0, double y1, F&& f) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    auto widen_down = [](double v) { return std::nextafter(std::nextafter(v, -inf), -inf); };
    auto widen_up = [](double v) { return std::nextafter(std::nextafter(v, inf), inf); };
    auto go_on = [&f](int s) {
      if constexpr (std::is_void_v<decltype(f(s))>) {
        f(s);
        return true;
      } else {
        return static_cast<bool>(f(s));
      }
    };
    query(0, order_.size(), 0, widen_down(x0), widen_up(x1), widen_down(y0), widen_up(y1), go_on);
  }

 private:
  double coord(int i, int axis) const { return axis == 0 ? p_[i].x : p_[i].y; }
  void build(std::size_t lo, std::size_t hi, int axis) {
    if (hi - lo <= 8) return;
    const std::size_t mid = (lo + hi) / 2;
    std::nth_element(order_.begin() + lo, order_.begin() + mid, order_.begin() + hi,
                     [&](int a, int b) { return coord(a, axis) < coord(b, axis); });
    build(lo, mid, 1 - axis);
    build(mid + 1, hi, 1 - axis);
  }
  // false once f asked to stop.
  template <class F>
  bool query(std::size_t lo, std::size_t hi, int axis, double x0, double x1, double y0, double y1, F& f) const {
    if (hi - lo <= 8) {
      for (std::size_t k = lo; k < hi; ++k) {
        const auto& q = p_[order_[k]];
        if (q.x >= x0 && q.x <= x1 && q.y >= y0 && q.y <= y1 && !f(order_[k])) return false;
      }
      return true;
    }
    const std::size_t mid = (lo + hi) / 2;
    const int m = order_[mid];
    const double split = coord(m, axis), low = axis == 0 ? x0 : y0, high = axis == 0 ? x1 : y1;
    if (p_[m].x >= x0 && p_[m].x <= x1 && p_[m].y >= y0 && p_[m].y <= y1 && !f(m)) return false;
    if (low <= split && !query(lo, mid, 1 - axis, x0, x1, y0, y1, f)) return false;
    return high < split || query(mid + 1, hi, 1 - axis, x0, x1, y0, y1, f);
  }
  const std::vector<predicates::Point2<double>>& p_;
  std::vector<int> order_;
};

}  // namespace anisocert::oracle
