// BWY §4 (Lemma 2 and §4.2): the certified γ_max against the exact decision, and the
// consistency of the §4.2 conditions with each other and with LS Theorem 9 / Theorem 11.

#include "property_tests/generators/rationals.hpp"
#include "theory/bwy_section4.hpp"
#include "numbers/decimal_enclosure.hpp"
#include "theory/ls_theorem11.hpp"
#include "theory/ls_theorem9.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::gen::rational_in;
using anisocert::gen::ten_to_minus;
using namespace anisocert::theory;
using namespace anisocert;

namespace {
const mpfr_prec_t prec = 256;

// G >= 1: exactly 1, within 10⁻² (where Lemma 2 can hold), or up to 1.2 (where it fails).
rc::Gen<Rational> distortion() {
  return rc::gen::oneOf(rc::gen::just(Rational(1)), rational_in(Rational(1), Rational(101, 100)),
                        rational_in(Rational(1), Rational(6, 5)));
}
rc::Gen<Rational> shape_bound() { return rational_in(Rational(1), Rational(10)); }
}  // namespace

// The decimals of γ_max(B) bracket the exact boundary of the rational condition: at lo the
// condition holds, just above hi it fails (the lhs is increasing in γ).
RC_GTEST_PROP(BWY_L2, GammaMaxSeparatesTheExactDecision, ()) {
  const Rational B = *shape_bound();
  const DecimalEnclosure d = to_decimal(bwy_lemma2_gamma_max(B, prec), 60);
  const Rational lo = parse_rational(d.lo), hi = parse_rational(d.hi);
  RC_ASSERT(lo > 1);
  RC_ASSERT(bwy_lemma2_gamma_max_bracket_verified(B, lo, hi));
  RC_ASSERT(bwy_lemma2_lhs(lo, B) <= 1);
  RC_ASSERT(bwy_lemma2_lhs(Rational(hi + ten_to_minus(70)), B) > 1);
  RC_ASSERT(bwy_s42_conditions(B, lo).lemma2);
}

RC_GTEST_PROP(BWY_L2, GammaMaxDecreasesAsBGrows, ()) {
  Rational a = *shape_bound(), b = *shape_bound();
  RC_PRE(a != b);
  if (b < a) std::swap(a, b);
  bool separated = false;
  for (mpfr_prec_t p = prec; p <= 8192 && !separated; p *= 2) {
    const Interval ga = bwy_lemma2_gamma_max(a, p), gb = bwy_lemma2_gamma_max(b, p);
    RC_ASSERT(!certainly_less(ga, gb));
    separated = certainly_less(gb, ga);
  }
  RC_ASSERT(separated);
}

// BWY's last paragraph of §4.2: (G² − 1)B² < 1 is what LS Corollary 10 needs, i.e. LS
// Theorem 9's χ(B, G) > 0. Lemma 2's condition implies it and G²√(G⁴−1) <= 1 (for B > 1 the
// factor (1+G)²(1+4G)²B² >= 100). G²√(G⁴−1) <= 1 ⇔ G⁸ − G⁴ − 1 <= 0 ⇔ G <= γ_LS(0°), LS
// Theorem 11's γ at θ_bound = 0.
RC_GTEST_PROP(BWY_S42, ConditionsAgreeWithLabelleShewchuk, ()) {
  const Rational B = *shape_bound(), G = *distortion();
  const BwyConditions c = bwy_s42_conditions(B, G);
  RC_CLASSIFY(c.lemma2, "lemma2 holds");
  RC_CLASSIFY(c.all(), "all hold");
  RC_ASSERT(c.angle_bound == (ls_chi(B, G) > 0));
  if (c.lemma2) RC_ASSERT(c.angle_bound && c.violator_factor);
  const Interval gamma0 = ls_t11_gamma(Rational(0), prec), g(G, prec);
  if (certainly_less(g, gamma0)) RC_ASSERT(c.violator_factor);
  if (certainly_less(gamma0, g)) RC_ASSERT(!c.violator_factor);
}

// Smaller distortion and larger B can only help: each condition is monotone.
RC_GTEST_PROP(BWY_S42, ConditionsAreMonotone, ()) {
  const Rational B = *shape_bound(), G = *distortion();
  const Rational t = *rational_in(Rational(0), Rational(1));
  const Rational G_smaller = 1 + (G - 1) * t;
  const Rational B_larger = B + *rational_in(Rational(0), Rational(5));
  const BwyConditions c = bwy_s42_conditions(B, G), smaller = bwy_s42_conditions(B, G_smaller);
  if (c.lemma2) RC_ASSERT(smaller.lemma2);
  if (c.violator_factor) RC_ASSERT(smaller.violator_factor);
  if (c.shape_factor) RC_ASSERT(smaller.shape_factor && bwy_s42_conditions(B_larger, G).shape_factor);
  if (c.angle_bound) RC_ASSERT(smaller.angle_bound);
}

// The exact decisions agree with the certified factors: G²√(G⁴−1) <= 1 ⇔ 1/(G²√(G⁴−1)) >= 1,
// and G²√(G²+1) <= B ⇔ B/(G²√(G²+1)) >= 1. Two independent code paths.
RC_GTEST_PROP(BWY_S42, ExactConditionsAgreeWithCertifiedFactors, ()) {
  const Rational B = *shape_bound(), G = *distortion();
  const BwyConditions c = bwy_s42_conditions(B, G);
  const BwyInterdistanceFactors f = bwy_s42_factors(B, G, prec);
  const Interval one(Rational(1), prec);
  RC_ASSERT(f.violator.has_value() == (G > 1));
  if (f.violator) {
    if (c.violator_factor) RC_ASSERT(!certainly_less(*f.violator, one));
    else RC_ASSERT(!certainly_less(one, *f.violator));
  }
  if (c.shape_factor) RC_ASSERT(!certainly_less(f.shape, one));
  else RC_ASSERT(!certainly_less(one, f.shape));
}
