// LU Theorem 4.5's parameter conditions at hand-checked rational points, exact boundaries
// included.

#include "theory/lu_theorem45.hpp"

#include <gtest/gtest.h>

using anisocert::Rational;
using namespace anisocert::theory;

TEST(LU_T45, StrictAtTheExactBoundaryOfLemma43) {
  // δ = 1/2, γ₀ = 3/2: (1−δ)³ρ₀ = ρ₀/8 and 2γ₀³ = 27/4, equal at ρ₀ = 54.
  LuConditions at = lu_t45_conditions({Rational(54), Rational(3, 2), Rational(1, 2), Rational(1000)});
  EXPECT_FALSE(at.lemma43);
  EXPECT_TRUE(at.rho0_above_2 && at.delta_rho0 && at.delta_beta && at.lemma44);
  LuConditions above = lu_t45_conditions({Rational(54) + Rational(1, 1000000), Rational(3, 2), Rational(1, 2), Rational(1000)});
  EXPECT_TRUE(above.all());
}

// Each of Theorem 4.5's other strict conditions at its exact boundary, δ = 1/2 ((1−δ)³ = 1/8):
// (1−δ)³ρ₀ = 2 at ρ₀ = 16, (1−δ)³β = 2 at β = 16, and with γ₀ = 3/2 (2γ₀³ = 27/4)
// (1−δ)³β = 2γ₀³ at β = 54. At the boundary the condition fails; just above it holds.
TEST(LU_T45, StrictAtTheExactBoundariesOfTheOtherConditions) {
  const Rational half(1, 2), tiny(1, 1000000);
  const LuConditions rho = lu_t45_conditions({Rational(16), Rational(11, 10), half, Rational(1000)});
  EXPECT_FALSE(rho.delta_rho0);
  EXPECT_TRUE(lu_t45_conditions({Rational(16) + tiny, Rational(11, 10), half, Rational(1000)}).delta_rho0);
  const LuConditions beta = lu_t45_conditions({Rational(1000), Rational(11, 10), half, Rational(16)});
  EXPECT_FALSE(beta.delta_beta);
  EXPECT_TRUE(lu_t45_conditions({Rational(1000), Rational(11, 10), half, Rational(16) + tiny}).delta_beta);
  const LuConditions l44 = lu_t45_conditions({Rational(1000), Rational(3, 2), half, Rational(54)});
  EXPECT_FALSE(l44.lemma44);
  EXPECT_TRUE(l44.rho0_above_2 && l44.delta_rho0 && l44.delta_beta && l44.lemma43);
  EXPECT_TRUE(lu_t45_conditions({Rational(1000), Rational(3, 2), half, Rational(54) + tiny}).all());
}

TEST(LU_T45, TypicalParameters) {
  // ρ₀ = 3, γ₀ = 1.1, δ = 0.1: (0.9)³·3 = 2.187 < 2·1.331 = 2.662, so Lemma 4.3 fails.
  LuConditions c = lu_t45_conditions({Rational(3), Rational(11, 10), Rational(1, 10), Rational(3)});
  EXPECT_TRUE(c.rho0_above_2);
  EXPECT_TRUE(c.delta_rho0);  // 2.187 > 2
  EXPECT_FALSE(c.lemma43);
  EXPECT_FALSE(c.lemma44);
  EXPECT_FALSE(c.all());
  // ρ₀ = β = 4: 0.729·4 = 2.916 > 2.662.
  EXPECT_TRUE(lu_t45_conditions({Rational(4), Rational(11, 10), Rational(1, 10), Rational(4)}).all());
}

TEST(LU_T45, RejectsParametersOutsideThePapersRanges) {
  EXPECT_THROW(lu_t45_conditions({Rational(3), Rational(1), Rational(1, 10), Rational(3)}), std::invalid_argument);
  EXPECT_THROW(lu_t45_conditions({Rational(0), Rational(2), Rational(1, 10), Rational(3)}), std::invalid_argument);
  EXPECT_THROW(lu_t45_conditions({Rational(3), Rational(2), Rational(0), Rational(3)}), std::invalid_argument);
  EXPECT_THROW(lu_t45_conditions({Rational(3), Rational(2), Rational(1, 10), Rational(-1)}), std::invalid_argument);
}
