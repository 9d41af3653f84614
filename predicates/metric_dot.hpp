#pragma once
// The M-inner product of two vectors from a common origin o: (p − o)ᵀ M (r − o).
// Degree 2 in the coordinates, 1 in the metric. One kernel serves
//   - each half of the wedge (LS Definition 2: (q − v)ᵀ M_v (w − v) > 0),
//   - the acute/obtuse test of an angle measured by M (LS Theorem 9, Corollary 10),
//   - encroachment of a segment (LU Definition 3.16, with o = p).

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct MetricDotKernel {
  static constexpr const char* name = "metric inner product";
  static constexpr std::size_t arity = 9;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"p.x", "p.y", "o.x", "o.y", "r.x",
                                                         "r.y", "M.m11", "M.m12", "M.m22"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return bilinear_form(x[6], x[7], x[8], T(x[0] - x[2]), T(x[1] - x[3]), T(x[4] - x[2]), T(x[5] - x[3]));
  }
};

// sign((p − o)ᵀ M (r − o))
template <class S>
Sign metric_dot_sign(const Point2<S>& p, const Point2<S>& o, const Point2<S>& r, const Sym2<S>& M) {
  return filtered_sign<MetricDotKernel>(std::array<S, 9>{p.x, p.y, o.x, o.y, r.x, r.y, M.m11, M.m12, M.m22});
}

}  // namespace anisocert::predicates
