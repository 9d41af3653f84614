#pragma once
// LS Theorem 11 (Labelle & Shewchuk 2003, §10): the distortion bound γ(θ_bound), the angle
// between adjoining segments, the minimal-distance factor, and the upper limit of θ_bound.
// Angles are in degrees; θ is an exact rational number of degrees.

#include "numbers/interval.hpp"

namespace anisocert::theory {

// P(γ) = γ⁸ + 2γ⁴ sqrt(γ² + 1) sin θ − γ⁴ − 1, the polynomial whose root > 1 is γ(θ).
Interval ls_t11_polynomial(const Interval& gamma, const Interval& sin_theta);

// sin θ for θ in degrees.
Interval ls_t11_sin_theta(const Rational& theta_deg, mpfr_prec_t prec);

// arcsin(1 / (2 sqrt 2)) in degrees (≈ 20.7°), the supremum of admissible θ_bound.
Interval ls_t11_theta_max_deg(mpfr_prec_t prec);

// Exact decision of 0 <= θ < arcsin(1 / (2 sqrt 2)) (in degrees). See the .cpp for why the
// comparison always terminates. Throws std::runtime_error if θ has so many digits that
// 2^20 bits of precision cannot separate it from the bound.
bool ls_t11_theta_admissible(const Rational& theta_deg);

// γ(θ): the unique real root > 1 of P. Throws std::invalid_argument unless
// ls_t11_theta_admissible(θ).
// The result is an enclosure [lo, hi] with P(lo) certainly < 0 < P(hi) certainly.
Interval ls_t11_gamma(const Rational& theta_deg, mpfr_prec_t prec);

// The check a reader can repeat on printed rationals lo < hi: P(lo) < 0 < P(hi), evaluated
// with outward rounding, which proves γ(θ) ∈ (lo, hi) (P is increasing on [1, ∞)); false for
// an inadmissible θ.
bool ls_t11_gamma_bracket_verified(const Rational& theta_deg, const Rational& lo, const Rational& hi,
                                   mpfr_prec_t prec);

// The angle condition on adjoining segments, 2 arcsin(γ² / 2), in degrees.
Interval ls_t11_segment_angle_deg(const Interval& gamma);

// The minimal-distance factor 1 / ((γ⁵ + γ³) sqrt(γ² + 1)) of bdr_min(γ) (= LS Lemma 23's).
Interval ls_t11_distance_factor(const Interval& gamma);

}  // namespace anisocert::theory
