// BWY §4 conditions at hand-checked rational points, including exact boundaries.

#include "theory/bwy_section4.hpp"

#include <gtest/gtest.h>

using anisocert::parse_rational;
using anisocert::Rational;
using namespace anisocert::theory;

TEST(BWY_S42, IsotropicCaseSatisfiesEverything) {
  // G = 1: every (G² − 1) factor vanishes; G⁴(G²+1) = 2 <= B² = 9/4.
  BwyConditions c = bwy_s42_conditions(Rational(3, 2), Rational(1));
  EXPECT_TRUE(c.all());
  BwyInterdistanceFactors f = bwy_s42_factors(Rational(3, 2), Rational(1), 200);
  EXPECT_FALSE(f.violator.has_value());  // d_min / 0: no bound from that term
  EXPECT_TRUE(f.lfs.contains(Rational(1)));
  // B / (G² √(G²+1)) = (3/2)/√2; its square is 9/8.
  EXPECT_TRUE(sqr(f.shape).contains(Rational(9, 8)));
}

TEST(BWY_S42, ShapeConditionFailsBelowSqrt2) {
  // G = 1, B = 1.4: G⁴(G²+1) = 2 > 1.96.
  BwyConditions c = bwy_s42_conditions(parse_rational("1.4"), Rational(1));
  EXPECT_FALSE(c.shape_factor);
  EXPECT_TRUE(c.lemma2 && c.violator_factor && c.angle_bound);
}

TEST(BWY_S42, AngleConditionIsStrictAtItsExactBoundary) {
  // (G² − 1) B² = (25/16 − 1)(16/9) = 1 exactly for B = 4/3, G = 5/4.
  EXPECT_FALSE(bwy_s42_conditions(Rational(4, 3), Rational(5, 4)).angle_bound);
  EXPECT_TRUE(bwy_s42_conditions(Rational(4, 3) - Rational(1, 1000000000), Rational(5, 4)).angle_bound);
}

TEST(BWY_S42, Lemma2FailsForVisibleDistortion) {
  // G = 1.1, B = 1.5: (0.21)(4.41)(29.16)(5.0625) ≈ 136.7 > 1.
  EXPECT_FALSE(bwy_s42_conditions(parse_rational("1.5"), parse_rational("1.1")).lemma2);
  // G = 1.0009, B = 1.5: (0.00180081)(4.00360081)(25.03601296)(5.0625) ≈ 0.914 <= 1.
  EXPECT_TRUE(bwy_s42_conditions(parse_rational("1.5"), parse_rational("1.0009")).all());
}

TEST(BWY_L2, ExponentsArePinned) {
  // (2² − 1)(1 + 2)²(1 + 8)² 2⁴ = 3 · 9 · 81 · 16 = 34992 (by hand).
  EXPECT_EQ(bwy_lemma2_lhs(Rational(2), Rational(2)), Rational(34992));
  // γ_max by a second engine (mpmath findroot at 50 digits, run by the reviewer of this code):
  // B = 2: 1.000312197735630952220936…, B = 3/2: 1.000984645169814234945220…
  EXPECT_TRUE(bwy_lemma2_gamma_max(Rational(2), 256)
                  .inside(parse_rational("1.0003121977356309522209"), parse_rational("1.0003121977356309522210")));
  EXPECT_TRUE(bwy_lemma2_gamma_max(Rational(3, 2), 256)
                  .inside(parse_rational("1.0009846451698142349452"), parse_rational("1.0009846451698142349453")));
}

TEST(BWY_S42, ViolatorFactorJustAboveOneIsDefined) {
  // G = 1 + 10⁻⁸⁰: G⁴ − 1 > 0 exactly, though 256-bit intervals of G⁴ reach 1 (review finding).
  const Rational G = 1 + Rational(1, boost::multiprecision::pow(anisocert::Integer{10}, 80));
  BwyInterdistanceFactors f = bwy_s42_factors(Rational(2), G, 256);
  ASSERT_TRUE(f.violator.has_value());
  EXPECT_TRUE(f.violator->certainly_positive());
}

// A bracket of γ_max must have the left-hand side ≤ 1 at its low end and ≥ 1 at its high end. For
// B = 2 the sign change lies near 1.0003 (above): [1, 11/10] holds it; [2, 2] does not, since the
// left-hand side at 2 is 34992 > 1 at both ends; nor does [1, 1] (0 at both ends).
TEST(BWY_L2, GammaMaxBracketNeedsTheSignChange) {
  EXPECT_TRUE(bwy_lemma2_gamma_max_bracket_verified(Rational(2), Rational(1), Rational(11, 10)));
  EXPECT_FALSE(bwy_lemma2_gamma_max_bracket_verified(Rational(2), Rational(2), Rational(2)));
  EXPECT_FALSE(bwy_lemma2_gamma_max_bracket_verified(Rational(2), Rational(1), Rational(1)));
  EXPECT_FALSE(bwy_lemma2_gamma_max_bracket_verified(Rational(2), Rational(11, 10), Rational(1)));
}

TEST(BWY_L2, GammaMaxNeedsBAboveOne) {
  EXPECT_THROW(bwy_lemma2_gamma_max(Rational(1), 128), std::invalid_argument);
  EXPECT_THROW(bwy_s42_conditions(Rational(1), Rational(1)), std::invalid_argument);
  EXPECT_THROW(bwy_s42_conditions(Rational(2), Rational(99, 100)), std::invalid_argument);
  EXPECT_THROW(bwy_s42_factors(Rational(1), Rational(1), 128), std::invalid_argument);
  EXPECT_THROW(bwy_s42_factors(Rational(2), Rational(99, 100), 128), std::invalid_argument);
}
