#pragma once
// A constrained subsegment s = ab against sites with their own metrics (LS §9's encroachment when
// metrics differ). Along s, z(t) = a + t(b − a), each squared distance is a quadratic in t,
//   q_u(t) = t² |b − a|²_u + 2t (b − a)ᵀM_u(a − u) + |a − u|²_u,
// with rational coefficients, so every question about which site is nearest where along s is
// decided exactly: the ends of the ranges are 0, 1 and roots p ± q√D, compared by
// predicates/sqrt_sign.
#include "numbers/rational.hpp"
#include "refiners/common/distance_function.hpp"

#include <optional>
#include <vector>

namespace anisocert::refiners::common {

using predicates::Point2;

// w's closed cell among a, b and w meets s: q_w(t) ≤ q_a(t) and q_w(t) ≤ q_b(t) for some t in
// [0, 1]. When no other site is nearer than a or b anywhere on s (no subsegment is encroached), this
// is whether w's cell, were w inserted, would meet s. Exact: with `filter`, q_w − q_a and q_w − q_b
// are bounded in FilterInterval on pieces of [0, 1] first (most sites are far from s, and the
// answer is then decided there), and in rationals only when that does not decide
// (tests/refiner_ls_test.cpp compares the two).
bool reaches(const MetricSite& a, const MetricSite& b, const MetricSite& w, bool filter = true);

// The t in (0, 1) with q_a(t) = q_b(t), LS §9's "midpoint" d_a(z) = d_b(z), in doubles.
double midpoint_parameter(const MetricSite& a, const MetricSite& b);

// The ranges of t in [0, 1] where w is at least as near as every site of `others`, in doubles
// (for choosing a split point, which is then checked exactly: nearest_at).
std::vector<std::pair<double, double>> nearest_ranges(const Point2<double>& a, const Point2<double>& b, const MetricSite& w,
                                                      const std::vector<MetricSite>& others);

// w is at least as near to the rational point z as every site of `others`: z lies in w's closed
// cell among them. Exact.
bool nearest_at(const Point2<Rational>& z, const MetricSite& w, const std::vector<MetricSite>& others);

}  // namespace anisocert::refiners::common
