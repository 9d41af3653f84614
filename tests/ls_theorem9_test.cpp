// LS Theorem 9, Corollary 10 and the Lemma factors at rational points with closed forms
// (all expected values worked out by hand in the comments).

#include "theory/ls_lemma_factors.hpp"
#include "theory/ls_theorem9.hpp"

#include <gtest/gtest.h>

using anisocert::parse_rational;
using anisocert::Rational;
using namespace anisocert::theory;
using namespace anisocert;

namespace {
const mpfr_prec_t prec = 200;
Interval I(const Rational& q) { return Interval(q, prec); }
// x encloses q and is narrow: within q ± 10⁻⁵⁰ (200 bits give about 60 digits).
bool tight(const Interval& x, const Rational& q) {
  const Rational eps(1, boost::multiprecision::pow(anisocert::Integer{10}, 50));
  return x.contains(q) && x.inside(q - eps, q + eps);
}
}  // namespace

TEST(LS_T9, ChiClosedForms) {
  EXPECT_EQ(ls_chi(Rational(1), Rational(1)), Rational(1, 2));     // 1/2 − 0
  EXPECT_EQ(ls_chi(Rational(4, 3), Rational(5, 4)), Rational(0));  // 3/8 − (9/16)(4/3)/2 = 0
  EXPECT_EQ(ls_chi(Rational(2), Rational(5, 4)), Rational(1, 4) - Rational(9, 16));
  // The interval version of the same formula encloses the exact value.
  EXPECT_TRUE(ls_chi(I(Rational(7, 5)), I(Rational(9, 8))).contains(ls_chi(Rational(7, 5), Rational(9, 8))));
}

TEST(LS_T9, RangesAreDecidedExactly) {
  EXPECT_TRUE(ls_t9_gamma_in_range(Rational(1)));
  EXPECT_FALSE(ls_t9_gamma_in_range(parse_rational("0.99999")));
  EXPECT_TRUE(ls_t9_gamma_in_range(parse_rational("1.41421")));   // 1.41421² = 1.9999899...
  EXPECT_FALSE(ls_t9_gamma_in_range(parse_rational("1.41422")));  // 1.41422² = 2.0000182...
  EXPECT_FALSE(ls_t9_beta_in_range(parse_rational("0.7071")));    // 0.7071² = 0.49999041
  EXPECT_TRUE(ls_t9_beta_in_range(parse_rational("0.7072")));     // 0.7072² = 0.50013184
}

TEST(LS_T9, AngleBoundsAtGammaOneAreThirtyAndHundredTwenty) {
  // β = 1, γ = 1: χ = 1/2, arcsin χ = 30°, and Corollary 10 gives [30°, 2·arccos(1/2) = 120°].
  Interval chi = I(Rational(1, 2)), one = I(Rational(1));
  EXPECT_TRUE(tight(ls_t9_min_angle_deg(chi), Rational(30)));
  EXPECT_TRUE(tight(ls_c10_min_angle_deg(chi, one), Rational(30)));
  EXPECT_TRUE(tight(ls_c10_max_angle_deg(chi, one), Rational(120)));
  EXPECT_THROW(ls_t9_min_angle_deg(I(Rational(0))), std::domain_error);
}

TEST(LS_C10, BoundsAtChiOverGammaSquaredOneHalf) {
  // χ = 25/32, γ = 5/4: χ/γ² = (25/32)/(25/16) = 1/2, so [arcsin(1/2), 2·arccos(1/2)] = [30°, 120°].
  Interval chi = I(Rational(25, 32)), gamma = I(Rational(5, 4));
  EXPECT_TRUE(tight(ls_c10_min_angle_deg(chi, gamma), Rational(30)));
  EXPECT_TRUE(tight(ls_c10_max_angle_deg(chi, gamma), Rational(120)));
}

TEST(LS_Lemmas, FactorsAtRationalClosedForms) {
  // γ = 5/4: γ² − 1 = 9/16, so Lemma 5's 1/√(γ²−1) = 4/3; γ³ + γ = 125/64 + 80/64 = 205/64.
  EXPECT_TRUE(tight(ls_lemma5_factor(I(Rational(5, 4))), Rational(4, 3)));
  EXPECT_TRUE(tight(ls_lemma14_factor(I(Rational(5, 4))), Rational(64, 205)));
  // γ = 3/4: √(γ²+1) = 5/4, γ² = 9/16, γ³ = 27/64, γ⁴ = 81/256, γ⁵ = 243/1024.
  EXPECT_TRUE(tight(ls_lemma18_factor(I(Rational(3, 4))), Rational(45, 64)));
  EXPECT_TRUE(tight(ls_lemma21_site_factor(I(Rational(3, 4))), Rational(15, 16)));
  EXPECT_TRUE(tight(ls_lemma21_bdr_factor(I(Rational(3, 4))), Rational(256, 225)));
  EXPECT_TRUE(tight(ls_lemma23_factor(I(Rational(3, 4))), Rational(4096, 3375)));
  // γ = 1 is outside Lemma 5's range, and the error says so (not a division by zero further on).
  try {
    ls_lemma5_factor(I(Rational(1)));
    ADD_FAILURE() << "γ = 1 accepted";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("LS Lemma 5 factor needs γ > 1"), std::string::npos) << e.what();
  }
}
