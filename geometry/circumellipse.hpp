#pragma once
// The circumellipse of a triangle abc in a metric M (LU Definition 2.1: the circle through a, b, c
// for the distance d_M, an ellipse in the plane): its centre c and squared M-radius r², with
// d_M(c, a) = d_M(c, b) = d_M(c, c) = r. The centre is a + x where
//   [g₁ᵀ; g₂ᵀ] x = [q₁; q₂],  gᵢ = M dᵢ,  qᵢ = ½ dᵢᵀ M dᵢ,  d₁ = b − a, d₂ = c − a,
// solved by Cramer's rule, and r² = xᵀ M x.
//
// One construction for every number type T, as the predicates' kernels are (DESIGN.md § Style):
// double (the refiners' floating point), FilterInterval (an enclosure, the certifier's filters) and
// Rational (exact). T needs +, −, ·, / (an interval divisor containing 0 gives the whole line).
// A flat triangle has no circumellipse: det = 0 gives ±∞ or NaN in double, the whole line in
// intervals, and a division by zero in rationals (callers test orientation first).
#include "predicates/point.hpp"

namespace anisocert::geometry {

template <class T>
struct Circumellipse {
  T x, y;     // the centre minus a
  T cx, cy;   // the centre
  T r2;       // the squared M-radius
};

template <class T>
Circumellipse<T> circumellipse(const predicates::Point2<T>& a, const predicates::Point2<T>& b,
                               const predicates::Point2<T>& c, const predicates::Sym2<T>& M) {
  const T d1x = b.x - a.x, d1y = b.y - a.y, d2x = c.x - a.x, d2y = c.y - a.y;
  const T g1x = M.m11 * d1x + M.m12 * d1y, g1y = M.m12 * d1x + M.m22 * d1y;
  const T g2x = M.m11 * d2x + M.m12 * d2y, g2y = M.m12 * d2x + M.m22 * d2y;
  const T half(0.5);
  const T q1 = half * (d1x * g1x + d1y * g1y), q2 = half * (d2x * g2x + d2y * g2y);
  const T det = g1x * g2y - g1y * g2x;
  const T x = (q1 * g2y - q2 * g1y) / det, y = (g1x * q2 - g2x * q1) / det;
  return {x, y, a.x + x, a.y + y, predicates::quadratic_form(M.m11, M.m12, M.m22, x, y)};
}

}  // namespace anisocert::geometry
