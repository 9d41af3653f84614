#pragma once
// LU Definition 3.16: p encroaches the segment ab for the metric M when p lies strictly inside
// the diametral M-circle of ab, i.e. the M-angle apb is obtuse: (a − p)ᵀ M (b − p) < 0.
// Zero: p on the circle (not encroaching; the Gabriel tie).

#include "predicates/metric_dot.hpp"

namespace anisocert::predicates {

template <class S>
bool encroaches(const Point2<S>& p, const Point2<S>& a, const Point2<S>& b, const Sym2<S>& M) {
  return metric_dot_sign(a, p, b, M) == Sign::negative;
}

}  // namespace anisocert::predicates
