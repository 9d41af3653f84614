#include "theory/ls_lemma_factors.hpp"

#include <stdexcept>

namespace anisocert::theory {

Interval ls_lemma5_factor(const Interval& gamma) {
  Interval g2m1 = sqr(gamma) - 1;
  if (!g2m1.certainly_positive()) throw std::domain_error("LS Lemma 5 factor needs γ > 1");
  return 1 / sqrt(g2m1);
}

Interval ls_lemma14_factor(const Interval& gamma) { return 1 / (gamma * (sqr(gamma) + 1)); }

Interval ls_lemma18_factor(const Interval& gamma) { return sqr(gamma) * sqrt(sqr(gamma) + 1); }

Interval ls_lemma21_site_factor(const Interval& gamma) { return gamma * sqrt(sqr(gamma) + 1); }

Interval ls_lemma21_bdr_factor(const Interval& gamma) {
  Interval g2 = sqr(gamma);
  return 1 / (g2 * (g2 + 1));
}

Interval ls_lemma23_factor(const Interval& gamma) {
  Interval g2 = sqr(gamma);
  // (γ⁵ + γ³) sqrt(γ² + 1) = γ³ (γ² + 1) sqrt(γ² + 1)
  return 1 / (g2 * gamma * (g2 + 1) * sqrt(g2 + 1));
}

}  // namespace anisocert::theory
