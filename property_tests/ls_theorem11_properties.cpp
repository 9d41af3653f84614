// LS Theorem 11 (Labelle & Shewchuk 2003, §10): properties of γ(θ_bound), the segment angle
// and their enclosures, over generated θ_bound including values within 10⁻⁷⁰ of θ_max.

#include "property_tests/generators/rationals.hpp"
#include "numbers/decimal_enclosure.hpp"
#include "theory/ls_lemma_factors.hpp"
#include "theory/ls_theorem11.hpp"
#include "theory/ls_theorem9.hpp"
#include "theory/precision.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::gen::Theta;
using anisocert::gen::ten_to_minus;
using namespace anisocert::theory;
using namespace anisocert;

namespace {
// θ comes within 10⁻⁷⁰ of θ_max, where γ − 1 and angle − 60° are about 10⁻⁷¹: 512 bits
// (154 digits) keep those differences far above the enclosures' widths.
const mpfr_prec_t prec = 512;

Interval exact(const Rational& q) { return Interval(q, prec); }
}  // namespace

// The printed enclosure is checked, not trusted: P(lo) < 0 < P(hi) with outward rounding,
// and it has at least 30 correct digits (relative width <= 10⁻³⁰). Outward rounding of each
// endpoint to D digits may cost up to two units of the D-th digit, so D >= 32 is needed for
// 30 correct digits (the CLI prints 40 by default).
RC_GTEST_PROP(LS_T11, EnclosureBracketsTheRootWithThirtyDigits, ()) {
  const Theta theta = *anisocert::gen::admissible_theta();
  const int digits = *rc::gen::inRange(32, 81);
  RC_TAG(theta.kind);
  const Interval gamma = ls_t11_gamma(theta.value, working_precision(digits));
  const DecimalEnclosure d = to_decimal(gamma, digits);
  const Rational lo = parse_rational(d.lo), hi = parse_rational(d.hi);
  RC_ASSERT(mpfr_cmp_ui(gamma.lower(), 1) > 0);  // the root > 1 (printed, lo may round to 1)
  RC_ASSERT(ls_t11_gamma_bracket_verified(theta.value, lo, hi, gamma.precision()));
  RC_ASSERT(hi - lo <= lo * ten_to_minus(digits - 2));
}

RC_GTEST_PROP(LS_T11, GammaIsStrictlyDecreasing, ()) {
  Theta a = *anisocert::gen::admissible_theta();
  Theta b = *anisocert::gen::admissible_theta();
  RC_PRE(a.value != b.value);
  if (b.value < a.value) std::swap(a, b);
  RC_TAG(a.kind + "/" + b.kind);
  // γ(b) < γ(a) must be certified at some precision; distinct rationals need at most a few
  // thousand bits here (they differ by >= 10⁻¹⁵⁰).
  bool separated = false;
  for (mpfr_prec_t p = prec; p <= 8192 && !separated; p *= 2) {
    const Interval ga = ls_t11_gamma(a.value, p), gb = ls_t11_gamma(b.value, p);
    RC_ASSERT(!certainly_less(ga, gb));
    separated = certainly_less(gb, ga);
  }
  RC_ASSERT(separated);
}

// "This angle is less than 79°, and can be reduced arbitrarily close to 60°."
RC_GTEST_PROP(LS_T11, SegmentAngleLiesBetweenSixtyAndSeventyNine, ()) {
  const Theta theta = *anisocert::gen::admissible_theta();
  RC_TAG(theta.kind);
  const Interval angle = ls_t11_segment_angle_deg(ls_t11_gamma(theta.value, prec));
  RC_ASSERT(certainly_less(exact(Rational(60)), angle));
  RC_ASSERT(certainly_less(angle, exact(Rational(79))));
}

// θ_k = θ_max truncated to k decimals, so 0 < θ_max − θ_k < 10⁻ᵏ. γ is smooth at θ_max with
// dγ/dθ ≈ −0.0054 per degree and d(angle)/dγ ≈ 132 degrees at γ = 1, so the angle exceeds 60°
// by about 0.72 (θ_max − θ_k) < 10⁻ᵏ; and it decreases as θ_k increases toward θ_max.
RC_GTEST_PROP(LS_T11, SegmentAngleTendsToSixty, ()) {
  const int k = *rc::gen::inRange(1, 70);
  const Interval angle_k = ls_t11_segment_angle_deg(ls_t11_gamma(anisocert::gen::theta_max_truncated(k), prec));
  const Interval angle_next = ls_t11_segment_angle_deg(ls_t11_gamma(anisocert::gen::theta_max_truncated(k + 1), prec));
  RC_ASSERT(certainly_less(exact(Rational(60)), angle_k));
  RC_ASSERT(certainly_less(angle_k - 60, exact(ten_to_minus(k))));
  RC_ASSERT(!certainly_less(angle_k, angle_next));
}

// LS Lemma 18 derives Theorem 11's polynomial from Corollary 10 with β = γ²√(γ²+1):
// χ(β, γ)/γ² = sin θ_bound exactly at γ = γ(θ_bound). Evaluating Corollary 10's bound there
// must give θ_bound back: an independent path through ls_chi and ls_c10_min_angle_deg.
RC_GTEST_PROP(LS_T11, Lemma18SubstitutionGivesThetaBack, ()) {
  const Theta theta = *anisocert::gen::admissible_theta();
  RC_PRE(theta.value > 0);  // arcsin(χ/γ²) needs χ > 0
  RC_TAG(theta.kind);
  const Interval gamma = ls_t11_gamma(theta.value, prec);
  const Interval beta = ls_lemma18_factor(gamma);
  const Interval angle = ls_c10_min_angle_deg(ls_chi(beta, gamma), gamma);
  RC_ASSERT(angle.contains(theta.value));
  RC_ASSERT(certainly_less(angle - angle, exact(ten_to_minus(30))));  // angle − angle spans the width
}
