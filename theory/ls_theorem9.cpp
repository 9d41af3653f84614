#include "theory/ls_theorem9.hpp"

#include <stdexcept>

namespace anisocert::theory {

bool ls_t9_gamma_in_range(const Rational& gamma) { return gamma >= 1 && gamma * gamma <= 2; }

bool ls_t9_beta_in_range(const Rational& beta) { return beta > 0 && 2 * beta * beta >= 1; }

Interval ls_t9_min_angle_deg(const Interval& chi) {
  if (!chi.certainly_positive()) throw std::domain_error("LS Theorem 9 angle bound needs χ > 0");
  return degrees(asin(chi));
}

Interval ls_c10_min_angle_deg(const Interval& chi, const Interval& gamma) {
  if (!chi.certainly_positive()) throw std::domain_error("LS Corollary 10 angle bound needs χ > 0");
  return degrees(asin(chi / sqr(gamma)));
}

Interval ls_c10_max_angle_deg(const Interval& chi, const Interval& gamma) {
  if (!chi.certainly_positive()) throw std::domain_error("LS Corollary 10 angle bound needs χ > 0");
  return 2 * degrees(acos(chi / sqr(gamma)));
}

}  // namespace anisocert::theory
