#pragma once
// The distance functions of LS §2 on boxes, for any interval type T (FilterInterval for the fast
// path, MPFI's Interval when a decision needs more bits, Rational at exact points):
//   Q_v(x) = d_v(x)² = (x − v)ᵀ M_v (x − v),   ∇Q_v(x) = 2 M_v (x − v).
// The bisector conic of v and w (LS Proposition 2) is Q_v − Q_w = 0. The form is kept
// un-expanded, which keeps the enclosures tight on small boxes around the sites' Voronoi vertices.

#include "predicates/point.hpp"

#include <array>

namespace anisocert::refiners::common {

using predicates::Point2;
using predicates::Sym2;

// A site as a refiner knows it: its point and its metric, doubles that denote the rationals they
// are (LS §4: M_v = M(v), sampled once).
struct MetricSite {
  Point2<double> p;
  Sym2<double> M;
};

// A site's five numbers in T.
template <class T>
struct SiteIn {
  T x, y, m11, m12, m22;
};

// `of` maps a double to the T that denotes it (exactly).
template <class T, class Of>
SiteIn<T> lift(const MetricSite& s, Of of) {
  return {of(s.p.x), of(s.p.y), of(s.M.m11), of(s.M.m12), of(s.M.m22)};
}

template <class T>
T distance2(const SiteIn<T>& v, const T& x, const T& y) {
  const T dx = x - v.x, dy = y - v.y;
  return dx * (v.m11 * dx + v.m12 * dy) + dy * (v.m12 * dx + v.m22 * dy);
}

// ½ ∇Q_v(x) = M_v (x − v).
template <class T>
std::array<T, 2> half_gradient(const SiteIn<T>& v, const T& x, const T& y) {
  const T dx = x - v.x, dy = y - v.y;
  return {v.m11 * dx + v.m12 * dy, v.m12 * dx + v.m22 * dy};
}

}  // namespace anisocert::refiners::common
