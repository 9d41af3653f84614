// LS Theorem 9 and Corollary 10 (Labelle & Shewchuk 2003, §6): where χ > 0, and the angle
// bounds, over β and γ in the theorem's ranges, with exact χ = 0 configurations.

#include "property_tests/generators/rationals.hpp"
#include "theory/ls_lemma_factors.hpp"
#include "theory/ls_theorem9.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using anisocert::gen::rational_in;
using anisocert::gen::ten_to_minus;
using namespace anisocert::theory;
using namespace anisocert;

namespace {

struct BetaGamma {
  Rational beta, gamma;
  std::string kind;
};

// γ ∈ [1, √2], β >= 1/√2. Boundary class: χ = 0 exactly, i.e. β² (γ² − 1) = 1, from a
// Pythagorean triple (m²−n², 2mn, m²+n²) = (a, b, c) ordered so that b <= a: β = a/b,
// γ = c/a (then γ² − 1 = b²/a² = 1/β², and γ² <= 2 because b <= a).
rc::Gen<BetaGamma> beta_gamma() {
  auto generic = rc::gen::apply(
      [](Rational beta, Rational gamma) { return BetaGamma{beta, gamma, "generic"}; },
      rational_in(Rational(7072, 10000), Rational(20)), rational_in(Rational(1), Rational(141421, 100000)));
  auto gamma_one = rc::gen::map(rational_in(Rational(7072, 10000), Rational(20)),
                                [](Rational beta) { return BetaGamma{beta, Rational(1), "gamma_one"}; });
  auto boundary = rc::gen::mapcat(rc::gen::inRange(2, 200), [](int m) {
    return rc::gen::map(rc::gen::inRange(1, m), [m](int n) {
      long a = long(m) * m - long(n) * n, b = 2L * m * n, c = long(m) * m + long(n) * n;
      if (b > a) std::swap(a, b);
      return BetaGamma{Rational(a, b), Rational(c, a), "chi_zero"};
    });
  });
  auto near = rc::gen::mapcat(boundary, [](BetaGamma bg) {
    return rc::gen::map(rc::gen::pair(rc::gen::inRange(3, 60), rc::gen::element(-1, 1)), [bg](std::pair<int, int> kd) {
      return BetaGamma{bg.beta + kd.second * ten_to_minus(kd.first), bg.gamma, "near_chi_zero"};
    });
  });
  return rc::gen::oneOf(generic, gamma_one, boundary, near);
}

}  // namespace

// χ > 0 exactly where the theory says: χ = (1 − (γ²−1)β²)/(2β), so for γ > 1, χ > 0 ⇔
// β < 1/√(γ² − 1), Lemma 5's factor. The exact sign of χ against a certified interval.
RC_GTEST_PROP(LS_T9, ChiIsPositiveExactlyBelowTheLemma5Bound, ()) {
  const BetaGamma bg = *beta_gamma();
  RC_TAG(bg.kind);
  RC_PRE(ls_t9_beta_in_range(bg.beta) && ls_t9_gamma_in_range(bg.gamma));
  RC_PRE(bg.gamma > 1);  // Lemma 5's factor needs γ > 1 (at γ = 1, χ = 1/(2β) > 0 trivially)
  const Rational chi = ls_chi(bg.beta, bg.gamma);
  if (bg.kind == "chi_zero") RC_ASSERT(chi == 0);
  for (mpfr_prec_t p = 128; p <= 4096; p *= 2) {
    const Interval bound = ls_lemma5_factor(Interval(bg.gamma, p));
    if (chi == 0) {
      RC_ASSERT(bound.contains(bg.beta));
      return;
    }
    if (!bound.contains(bg.beta)) {  // β is below lo or above hi, compared exactly
      RC_ASSERT((chi > 0) == (mpfr_cmp_q(bound.lower(), bg.beta.backend().data()) > 0));
      return;
    }
  }
  RC_FAIL("β and 1/√(γ²−1) not separated at 4096 bits although χ ≠ 0");
}

// Every triangle has an angle <= 60° and one >= 60°, so a bound valid for all its angles
// must satisfy arcsin(χ/γ²) <= 60° <= 2·arccos(χ/γ²); measuring from p instead of the
// vertices can only weaken Theorem 9's bound: arcsin(χ/γ²) <= arcsin χ (γ >= 1); and the
// upper bound is what the lower one leaves of 180° to the third angle: 2·arccos(c) =
// 180° − 2·arcsin(c), computed here through acos and asin separately.
RC_GTEST_PROP(LS_C10, AngleBoundsAreConsistent, ()) {
  const BetaGamma bg = *beta_gamma();
  RC_TAG(bg.kind);
  RC_PRE(ls_t9_beta_in_range(bg.beta) && ls_t9_gamma_in_range(bg.gamma));
  const Rational chi = ls_chi(bg.beta, bg.gamma);
  RC_PRE(chi > 0);
  const mpfr_prec_t p = 200;
  const Interval chi_i(chi, p), gamma_i(bg.gamma, p);
  const Interval t9 = ls_t9_min_angle_deg(chi_i);
  const Interval c10_min = ls_c10_min_angle_deg(chi_i, gamma_i);
  const Interval c10_max = ls_c10_max_angle_deg(chi_i, gamma_i);
  const Interval sixty(Rational(60), p);
  RC_ASSERT(certainly_less(c10_min, sixty));
  RC_ASSERT(certainly_less(sixty, c10_max));
  RC_ASSERT(!certainly_less(t9, c10_min));
  if (bg.gamma == 1) RC_ASSERT(!certainly_less(c10_min, t9));  // equal when γ = 1
  RC_ASSERT((c10_max + 2 * c10_min).contains(Rational(180)));
}
