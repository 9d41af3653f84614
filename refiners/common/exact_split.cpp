#include "refiners/common/exact_split.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

namespace anisocert::refiners::common {

namespace {

// s + e = a + b exactly (Knuth's TwoSum).
std::pair<double, double> two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// The exponent t of the largest power of two 2ᵗ dividing x (x ≠ 0 and finite).
int trailing_exponent(double x) {
  int e;
  const double m = std::frexp(std::abs(x), &e);  // x = m 2ᵉ, m ∈ [1/2, 1)
  const auto mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
  return e - 53 + std::countr_zero(mantissa);
}

// The points u + k (w − u)/2ʲ are multiples of 2^min(t_u, t_d − j) (t_d for the exact difference)
// of magnitude < 2ᴱ; all are doubles when E − min(t_u, t_d − j) ≤ 53.
// (and, for subnormal ones, when min(t_u, t_d − j) ≥ −1074).
int halvings(double u, double w) {
  if (!std::isfinite(u) || !std::isfinite(w)) return 0;
  if (u == w) return INT_MAX;
  const auto [hi, lo] = two_sum(w, -u);
  if (!std::isfinite(hi)) return 0;  // |w − u| beyond the doubles
  const int td = trailing_exponent(lo != 0 ? lo : hi);
  const int E = std::ilogb(std::max(std::abs(u), std::abs(w))) + 1;
  const int tu = u != 0 ? trailing_exponent(u) : INT_MAX;
  if (tu != INT_MAX && E - tu > 53) return 0;
  return std::max(0, std::min(53 - E + td, td + 1074));
}

// Between u ≠ w every double lies on an axis-parallel segment whose other coordinate is shared:
// halved h times, each piece (|w − u|/2ʰ long) still holds a double strictly inside while it is
// at least two units in the last place of the larger end.
int axis_halvings(double u, double w) {
  if (!std::isfinite(u) || !std::isfinite(w)) return 0;
  const double d = std::abs(w - u), ulp = std::nextafter(std::max(std::abs(u), std::abs(w)), INFINITY) - std::max(std::abs(u), std::abs(w));
  if (!std::isfinite(d) || !(ulp > 0)) return 0;
  return std::max(0, std::ilogb(d) - std::ilogb(ulp) - 2);
}

}  // namespace

int exact_halvings(const predicates::Point2<double>& a, const predicates::Point2<double>& b) {
  return std::min(halvings(a.x, b.x), halvings(a.y, b.y));
}

int split_halvings(const predicates::Point2<double>& a, const predicates::Point2<double>& b) {
  const int grid = exact_halvings(a, b);
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return grid;
  if (a.x == b.x && a.y != b.y) return std::max(grid, axis_halvings(a.y, b.y));
  if (a.y == b.y && a.x != b.x) return std::max(grid, axis_halvings(a.x, b.x));
  return grid;
}
int exact_halvings(const predicates::Point3<double>& a, const predicates::Point3<double>& b) {
  return std::min({halvings(a.x, b.x), halvings(a.y, b.y), halvings(a.z, b.z)});
}

namespace {

// (u + w)/2 when it is a double: an exact sum halved without loss (no underflow into
// subnormals), or, when the sum overflows (both beyond 2⁹⁷⁰, so their halves are exact), an
// exact sum of the halves.
std::optional<double> half_sum(double u, double w) {
  if (!std::isfinite(u) || !std::isfinite(w)) return std::nullopt;
  if (const auto [s, e] = two_sum(u, w); std::isfinite(s)) {
    if (e != 0 || (s / 2) * 2 != s) return std::nullopt;
    return s / 2;
  }
  const auto [s, e] = two_sum(u / 2, w / 2);
  if (e != 0) return std::nullopt;
  return s;
}

}  // namespace

std::optional<predicates::Point3<double>> exact_midpoint(const predicates::Point3<double>& a,
                                                         const predicates::Point3<double>& b) {
  const auto x = half_sum(a.x, b.x), y = half_sum(a.y, b.y), z = half_sum(a.z, b.z);
  if (!x || !y || !z) return std::nullopt;
  return predicates::Point3<double>{*x, *y, *z};
}

std::optional<predicates::Point2<double>> exact_midpoint(const predicates::Point2<double>& a,
                                                         const predicates::Point2<double>& b) {
  const auto x = half_sum(a.x, b.x), y = half_sum(a.y, b.y);
  if (!x || !y) return std::nullopt;
  return predicates::Point2<double>{*x, *y};
}

}  // namespace anisocert::refiners::common
