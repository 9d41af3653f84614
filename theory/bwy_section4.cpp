#include "theory/bwy_section4.hpp"

#include "theory/ls_lemma_factors.hpp"
#include "theory/sign_change_root.hpp"

#include <stdexcept>

namespace anisocert::theory {

Interval bwy_lemma2_gamma_max(const Rational& B, mpfr_prec_t prec) {
  if (!(B > 1)) throw std::invalid_argument("BWY Lemma 2 needs B > 1");
  Interval b(B, prec);
  return enclose_sign_change([&b](const Interval& g) { return bwy_lemma2_lhs(g, b) - 1; }, Rational(1), Rational(2),
                             prec);
}

bool bwy_lemma2_gamma_max_bracket_verified(const Rational& B, const Rational& lo, const Rational& hi) {
  return 1 <= lo && lo <= hi && bwy_lemma2_lhs(lo, B) <= 1 && bwy_lemma2_lhs(hi, B) >= 1;
}

BwyConditions bwy_s42_conditions(const Rational& B, const Rational& G) {
  if (!(B > 1) || !(G >= 1)) throw std::invalid_argument("BWY §4 needs B > 1 and G >= 1");
  const Rational G2 = G * G, G4 = G2 * G2;
  // With G >= 1 and B > 0 both sides of the square-root conditions are non-negative, so
  // squaring them is an equivalence: G⁴ (G⁴ − 1) <= 1 and G⁴ (G² + 1) <= B².
  return BwyConditions{
      .lemma2 = bwy_lemma2_lhs(G, B) <= 1,
      .violator_factor = G4 * (G4 - 1) <= 1,
      .shape_factor = G4 * (G2 + 1) <= B * B,
      .angle_bound = (G2 - 1) * B * B < 1,
  };
}

BwyInterdistanceFactors bwy_s42_factors(const Rational& B, const Rational& G, mpfr_prec_t prec) {
  if (!(B > 1) || !(G >= 1)) throw std::invalid_argument("BWY §4 needs B > 1 and G >= 1");
  Interval g(G, prec), b(B, prec);
  Interval g2 = sqr(g);
  std::optional<Interval> violator;
  // G⁴ − 1 exactly: an interval G⁴ − 1 could reach 0 for G just above 1.
  if (G > 1) violator = 1 / (g2 * sqrt(Interval(Rational(G * G * G * G - 1), prec)));
  return BwyInterdistanceFactors{
      .violator = violator,
      .shape = b / (g2 * sqrt(g2 + 1)),
      .bdr = ls_lemma23_factor(g),
      .lfs = 1 / g,
  };
}

}  // namespace anisocert::theory
