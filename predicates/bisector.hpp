#pragma once
// Side of the bisector (LS Definition 1, Proposition 2): sign(d_v(q)² − d_w(q)²) with
// d_v(q)² = (q − v)ᵀ M_v (q − v). Degree 2 in the coordinates, 1 in the metrics.
// Negative: q is strictly closer to v (in Vor(v) of the two-site diagram); zero: q is on the
// bisector conic of Proposition 2.

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct SideOfBisectorKernel {
  static constexpr const char* name = "side of bisector";
  static constexpr std::size_t arity = 12;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"q.x",    "q.y",    "v.x",    "v.y",
                                                         "Mv.m11", "Mv.m12", "Mv.m22", "w.x",
                                                         "w.y",    "Mw.m11", "Mw.m12", "Mw.m22"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return quadratic_form(x[4], x[5], x[6], T(x[0] - x[2]), T(x[1] - x[3])) -
           quadratic_form(x[9], x[10], x[11], T(x[0] - x[7]), T(x[1] - x[8]));
  }
};

template <class S>
Sign side_of_bisector(const Point2<S>& q, const Point2<S>& v, const Sym2<S>& Mv, const Point2<S>& w,
                      const Sym2<S>& Mw) {
  return filtered_sign<SideOfBisectorKernel>(
      std::array<S, 12>{q.x, q.y, v.x, v.y, Mv.m11, Mv.m12, Mv.m22, w.x, w.y, Mw.m11, Mw.m12, Mw.m22});
}

}  // namespace anisocert::predicates
