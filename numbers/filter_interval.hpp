#pragma once
// The interval type of the filters: [lo, hi] of doubles, each operation computed with
// round-to-nearest and then widened by one ulp outward (std::nextafter). Round-to-nearest is
// within half an ulp of the exact result (also under gradual underflow, where the error is at
// most half the smallest subnormal), so the widened interval contains every exact result.
// Overflow gives infinite endpoints, which only makes the interval undecided.

#include "numbers/sign.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

namespace anisocert {

struct FilterInterval {
  double lo, hi;

  FilterInterval() : lo(0), hi(0) {}
  FilterInterval(double x) : lo(x), hi(x) {}  // NOLINT: a double is an exact point
  FilterInterval(double l, double h) : lo(l), hi(h) {}
  // A double interval around the rational q: GMP's mpq_get_d truncates towards zero (no
  // allocation, unlike a correctly rounded conversion), so q lies within one ulp of it, on the far
  // side from zero; overflow gives ±∞ and underflow 0 or a subnormal. Widening by one ulp on both
  // sides covers every case.
  static FilterInterval around(const Rational& q) {
    const double d = mpq_get_d(q.backend().data());
    return widen(d, d);
  }

  static FilterInterval widen(double l, double h) { return {next_down(l), next_up(h)}; }

  // std::nextafter towards +∞ / −∞ without the library call (the filters' hot path): a finite
  // non-zero double's neighbour is one step of its bit pattern, away from zero when positive.
  static double next_up(double x) {
    if (!(x < std::numeric_limits<double>::infinity())) return x;   // +∞, NaN
    if (x == 0) return std::numeric_limits<double>::denorm_min();    // +0 and −0
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    b = x > 0 ? b + 1 : b - 1;
    std::memcpy(&x, &b, sizeof b);
    return x;
  }
  static double next_down(double x) { return -next_up(-x); }

  // The sign, when every point of the interval has it; nothing when it contains 0 or is NaN.
  std::optional<Sign> sign() const {
    if (lo > 0) return Sign::positive;
    if (hi < 0) return Sign::negative;
    if (lo == 0 && hi == 0) return Sign::zero;
    return std::nullopt;
  }

  bool has_zero() const { return !(lo > 0 || hi < 0); }
  // [lo, hi] ⊂ (outer.lo, outer.hi).
  bool strictly_inside(const FilterInterval& outer) const { return lo > outer.lo && hi < outer.hi; }
  // A double of the interval near its middle (any point will do for centred forms and Krawczyk's
  // operator); NaN for an interval with a NaN end.
  FilterInterval midpoint() const {
    const double m = std::clamp(0.5 * lo + 0.5 * hi, lo, hi);  // halves first: no overflow
    return m;
  }
  friend std::optional<FilterInterval> intersection(const FilterInterval& a, const FilterInterval& b) {
    if (!(a.lo <= b.hi && b.lo <= a.hi)) return std::nullopt;  // disjoint, or NaN
    return FilterInterval(std::max(a.lo, b.lo), std::min(a.hi, b.hi));
  }
  double lower_double() const { return lo; }
  double upper_double() const { return hi; }

  friend FilterInterval operator+(const FilterInterval& a, const FilterInterval& b) {
    return widen(a.lo + b.lo, a.hi + b.hi);
  }
  friend FilterInterval operator-(const FilterInterval& a, const FilterInterval& b) {
    return widen(a.lo - b.hi, a.hi - b.lo);
  }
  friend FilterInterval operator-(const FilterInterval& a) { return {-a.hi, -a.lo}; }
  friend FilterInterval operator*(const FilterInterval& a, const FilterInterval& b) {
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    // A NaN among them (0 · ∞ after an overflow) makes the sum NaN, as does ∞ − ∞ (then a product
    // overflowed, and the whole line is right too).
    if (std::isnan(p1 + p2 + p3 + p4)) {
      constexpr double inf = std::numeric_limits<double>::infinity();
      return {-inf, inf};
    }
    return widen(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}));
  }
  // Times an exact double: the two products of the general case's four that differ.
  friend FilterInterval operator*(const FilterInterval& a, double s) {
    const double p1 = a.lo * s, p2 = a.hi * s;
    if (std::isnan(p1) || std::isnan(p2)) {  // 0 · ∞ after an overflow
      constexpr double inf = std::numeric_limits<double>::infinity();
      return {-inf, inf};
    }
    return widen(std::min(p1, p2), std::max(p1, p2));
  }
  friend FilterInterval operator*(double s, const FilterInterval& a) { return a * s; }
  // {x² : x ∈ a}, tighter than a · a when a holds 0.
  friend FilterInterval sqr(const FilterInterval& a) {
    if (a.lo >= 0) return widen(a.lo * a.lo, a.hi * a.hi);
    if (a.hi <= 0) return widen(a.hi * a.hi, a.lo * a.lo);
    return {0, next_up(std::max(a.lo * a.lo, a.hi * a.hi))};
  }
  // The least of two values, for every pair of points of the two intervals.
  friend FilterInterval min(const FilterInterval& a, const FilterInterval& b) {
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
  }
  // A divisor containing 0 (or NaN) gives the whole line.
  friend FilterInterval operator/(const FilterInterval& a, const FilterInterval& b) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (!(b.lo > 0 || b.hi < 0)) return {-inf, inf};
    const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    return widen(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
  }
  // The square root of the non-negative part (an end at or below 0 gives 0; NaN stays NaN).
  friend FilterInterval sqrt(const FilterInterval& a) {
    return {a.lo <= 0 ? 0 : std::max(0.0, next_down(std::sqrt(a.lo))), a.hi <= 0 ? 0 : next_up(std::sqrt(a.hi))};
  }
};

}  // namespace anisocert
