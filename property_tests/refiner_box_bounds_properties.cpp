// The subdivision's bounds over boxes (refiners/common/box_bounds.hpp), computed in doubles with one
// rounding bound, against the exact range in rationals: the extremes of a quadratic q(x, y) over a
// closed box lie among its corners, the stationary points of q along its four sides, and q's own
// stationary point, so the exact range is the least and greatest of q at those that are in the box.
// Scales from 2⁻⁴⁰ to 2⁴⁰ in the coordinates and 2⁻⁶⁰ to 2⁶⁰ in the metrics, anisotropy up to 10⁸,
// metrics next to singular, boxes from 2⁻⁵⁰ of the scale wide to as wide as it, some holding the site.
#include "numbers/rational.hpp"
#include "refiners/common/box_bounds.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using anisocert::Rational;
using namespace anisocert::refiners::common;

namespace {

// q(x, y) = A x² + B xy + C y² + D x + E y + F.
struct Quadratic {
  Rational A, B, C, D, E, F;
  Rational at(const Rational& x, const Rational& y) const { return A * x * x + B * x * y + C * y * y + D * x + E * y + F; }
};

Quadratic squared_distance(const MetricSite& u) {
  const Rational a(u.M.m11), m(u.M.m12), d(u.M.m22), x(u.p.x), y(u.p.y);
  return {a, 2 * m, d, -2 * (a * x + m * y), -2 * (m * x + d * y), a * x * x + 2 * m * x * y + d * y * y};
}

Quadratic minus(const Quadratic& p, const Quadratic& q) { return {p.A - q.A, p.B - q.B, p.C - q.C, p.D - q.D, p.E - q.E, p.F - q.F}; }

// The exact least and greatest values of q over the closed box.
std::pair<Rational, Rational> exact_range(const Quadratic& q, const Box& b) {
  const Rational x0(b.x0), x1(b.x1), y0(b.y0), y1(b.y1);
  std::vector<std::pair<Rational, Rational>> at{{x0, y0}, {x0, y1}, {x1, y0}, {x1, y1}};
  for (const Rational& X : {x0, x1})  // along x = X: C y² + (B X + E) y + …
    if (q.C != 0) {
      const Rational y = -(q.B * X + q.E) / (2 * q.C);
      if (y0 <= y && y <= y1) at.emplace_back(X, y);
    }
  for (const Rational& Y : {y0, y1})
    if (q.A != 0) {
      const Rational x = -(q.B * Y + q.D) / (2 * q.A);
      if (x0 <= x && x <= x1) at.emplace_back(x, Y);
    }
  if (const Rational det = 4 * q.A * q.C - q.B * q.B; det != 0) {
    const Rational x = (q.B * q.E - 2 * q.C * q.D) / det, y = (q.B * q.D - 2 * q.A * q.E) / det;
    if (x0 <= x && x <= x1 && y0 <= y && y <= y1) at.emplace_back(x, y);
  }
  Rational lo = q.at(at[0].first, at[0].second), hi = lo;
  for (const auto& [x, y] : at) {
    const Rational v = q.at(x, y);
    if (v < lo) lo = v;
    if (hi < v) hi = v;
  }
  return {lo, hi};
}

// A positive definite metric: eigenvalues λ and λ·r (r up to 10⁸, or a hair from 1), any direction;
// some next to singular: m22 a millionth above m12²/m11, an ulp above it (no longer certainly
// semi-definite with box_bounds' margin), or an ulp below it (indefinite).
rc::Gen<MetricSite> site(int scale) {
  return rc::gen::apply(
      [scale](int x, int y, int e, int log_r, int angle, int near_singular) {
        const double lambda = std::ldexp(1.0, e), r = std::pow(10.0, log_r / 10.0), t = angle * 0.001;
        const double c = std::cos(t), s = std::sin(t);
        MetricSite u{{std::ldexp(x / 1000.0, scale), std::ldexp(y / 1000.0, scale)}, {}};
        u.M = {lambda * (c * c + r * s * s), lambda * (1 - r) * c * s, lambda * (s * s + r * c * c)};
        const double singular = u.M.m12 * u.M.m12 / u.M.m11;
        if (near_singular == 1) u.M.m22 = singular * 1.000001;
        if (near_singular == 2) u.M.m22 = std::nextafter(singular, INFINITY);
        if (near_singular == 3) u.M.m22 = std::nextafter(singular, 0.0);
        return u;
      },
      rc::gen::inRange(-1000, 1001), rc::gen::inRange(-1000, 1001), rc::gen::inRange(-60, 61), rc::gen::inRange(0, 81),
      rc::gen::inRange(0, 6284), rc::gen::weightedElement<int>({{7, 0}, {1, 1}, {1, 2}, {1, 3}}));
}

rc::Gen<Box> box(int scale) {
  return rc::gen::apply(
      [scale](int x, int y, int wx, int wy) {
        const double x0 = std::ldexp(x / 1000.0, scale), y0 = std::ldexp(y / 1000.0, scale);
        return Box{x0, x0 + std::ldexp(1.0, scale - wx), y0, y0 + std::ldexp(1.0, scale - wy)};
      },
      rc::gen::inRange(-1000, 1001), rc::gen::inRange(-1000, 1001), rc::gen::inRange(0, 51), rc::gen::inRange(0, 51));
}

}  // namespace

RC_GTEST_PROP(BoxBounds, HoldEveryExactValueInTheBox, ()) {
  const int scale = *rc::gen::inRange(-40, 41);
  const MetricSite u = *site(scale), v = *site(scale);
  const Box b = *box(scale);
  RC_PRE(b.x0 < b.x1 && b.y0 < b.y1);
  const Quadratic qu = squared_distance(u), qv = squared_distance(v);
  const auto [lo, hi] = exact_range(qu, b);
  const Bounds d = squared_distance_bounds(u, b);
  RC_ASSERT(Rational(d.lo) <= lo);
  RC_ASSERT(hi <= Rational(d.hi));
  const auto [dlo, dhi] = exact_range(minus(qu, qv), b);
  const Bounds e = squared_distance_difference_bounds(u, v, b);
  RC_ASSERT(Rational(e.lo) <= dlo);
  RC_ASSERT(dhi <= Rational(e.hi));
}

// Not vacuous: the centred form overshoots the exact range by at most twice its quadratic term,
// |M₁₁|h_x² + 2|M₁₂|h_xh_y + |M₂₂|h_y² (the corner m ± h in g's direction is in the box), plus rounding
// (a bound as wide as [0, ∞] fails here): on boxes 2⁻²⁰ of the scale wide at the scale's distance.
RC_GTEST_PROP(BoxBounds, OvershootTheExactRangeByTheQuadraticTermAtMost, ()) {
  const int scale = *rc::gen::inRange(-40, 41);
  MetricSite u = *site(scale);
  u.p = {0, 0};
  const double x0 = std::ldexp(1.0, scale), w = std::ldexp(1.0, scale - 20);
  const Box b{x0, x0 + w, x0, x0 + w};
  const auto [lo, hi] = exact_range(squared_distance(u), b);
  const Bounds d = squared_distance_bounds(u, b);
  const Rational size = Rational(std::abs(u.M.m11) + 2 * std::abs(u.M.m12) + std::abs(u.M.m22));
  const Rational slack = size * Rational(w) * Rational(w) / 2 + size * Rational(4 * x0 * x0) * Rational(0x1p-40);
  RC_ASSERT(lo - slack <= Rational(d.lo));
  RC_ASSERT(Rational(d.hi) <= hi + slack);
}
