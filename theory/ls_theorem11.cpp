#include "theory/ls_theorem11.hpp"

#include "theory/ls_lemma_factors.hpp"
#include "theory/sign_change_root.hpp"

#include <stdexcept>

namespace anisocert::theory {

Interval ls_t11_polynomial(const Interval& gamma, const Interval& sin_theta) {
  Interval g2 = sqr(gamma);
  Interval g4 = sqr(g2);
  return sqr(g4) + 2 * (g4 * sqrt(g2 + 1) * sin_theta) - g4 - 1;
}

Interval ls_t11_sin_theta(const Rational& theta_deg, mpfr_prec_t prec) {
  return sin(radians(Interval(theta_deg, prec)));
}

Interval ls_t11_theta_max_deg(mpfr_prec_t prec) {
  // 1 / (2 sqrt 2) = sqrt(1/8)
  return degrees(asin(sqrt(Interval(Rational(1, 8), prec))));
}

bool ls_t11_theta_admissible(const Rational& theta_deg) {
  if (theta_deg < 0) return false;
  // θ_max is not a rational number of degrees: if it were, θ_max would be a rational multiple
  // of π with cos(2 θ_max) = 1 − 2 sin²θ_max = 3/4 rational, and Niven's theorem allows only
  // cos ∈ {0, ±1/2, ±1} there. So θ ≠ θ_max for every rational θ, and the enclosures below
  // separate them once the precision is high enough.
  for (mpfr_prec_t prec = 128; prec <= (mpfr_prec_t{1} << 20); prec *= 2) {
    Interval theta(theta_deg, prec);
    Interval theta_max = ls_t11_theta_max_deg(prec);
    if (certainly_less(theta, theta_max)) return true;
    if (certainly_less(theta_max, theta)) return false;
  }
  throw std::runtime_error("θ = " + to_exact_string(theta_deg) +
                           " could not be compared with arcsin(1/(2√2)) within 2^20 bits of precision");
}

Interval ls_t11_gamma(const Rational& theta_deg, mpfr_prec_t prec) {
  // The argument below needs sin θ >= 0 and θ < θ_max (θ = 170° also has P(1) < 0).
  if (!ls_t11_theta_admissible(theta_deg))
    throw std::invalid_argument("ls_t11_gamma: θ = " + to_exact_string(theta_deg) + " is not admissible");
  // For γ >= 1 and sin θ >= 0, P'(γ) = 8γ⁷ − 4γ³ + 2 sin θ (4γ³ sqrt(γ²+1) + γ⁵ / sqrt(γ²+1)) > 0,
  // so P is strictly increasing on [1, ∞); P(1) = 2 sqrt 2 sin θ − 1 < 0 exactly when θ < θ_max,
  // and P(2) = 239 + 32 sqrt 5 sin θ > 0. Hence the root > 1 is unique and lies in (1, 2).
  // Near θ_max, P(1) is tiny and may need more than `prec` bits to be certified negative.
  for (mpfr_prec_t p = prec; p <= (mpfr_prec_t{1} << 21); p *= 2) {
    Interval s = ls_t11_sin_theta(theta_deg, p);
    auto P = [&s](const Interval& g) { return ls_t11_polynomial(g, s); };
    if (brackets_sign_change(P, Rational(1), Rational(2), p)) return enclose_sign_change(P, Rational(1), Rational(2), p);
  }
  throw std::runtime_error("ls_t11_gamma: P(1) < 0 not certified within 2^21 bits for θ = " + to_exact_string(theta_deg));
}

bool ls_t11_gamma_bracket_verified(const Rational& theta_deg, const Rational& lo, const Rational& hi,
                                   mpfr_prec_t prec) {
  if (!ls_t11_theta_admissible(theta_deg)) return false;
  Interval s = ls_t11_sin_theta(theta_deg, prec);
  return lo >= 1 && brackets_sign_change([&s](const Interval& g) { return ls_t11_polynomial(g, s); }, lo, hi, prec);
}

Interval ls_t11_segment_angle_deg(const Interval& gamma) { return degrees(2 * asin(sqr(gamma) / 2)); }

Interval ls_t11_distance_factor(const Interval& gamma) { return ls_lemma23_factor(gamma); }

}  // namespace anisocert::theory
