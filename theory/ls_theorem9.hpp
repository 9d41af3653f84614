#pragma once
// LS Theorem 9 and Corollary 10 (Labelle & Shewchuk 2003, §6): the quality parameter χ and
// the angle bounds it gives. Angles in degrees.

#include "numbers/interval.hpp"

namespace anisocert::theory {

// χ(β, γ) = 1/(2β) − (γ² − 1) β / 2. One formula for exact rationals (the sign of χ decides
// "q is wedged", Theorem 9) and for intervals (β, γ irrational, e.g. Lemma 18's β).
template <class T>
T ls_chi(const T& beta, const T& gamma) {
  return T(1 / (2 * beta)) - T((gamma * gamma - 1) * beta / 2);
}

// Theorem 9's parameter ranges, decided exactly: 1 <= γ <= sqrt 2 and β >= 1/sqrt 2.
bool ls_t9_gamma_in_range(const Rational& gamma);
bool ls_t9_beta_in_range(const Rational& beta);

// Theorem 9: every angle θ of the triangle has θ >= arcsin χ (measured from some vertex).
// Requires 0 < χ <= 1 (certainly).
Interval ls_t9_min_angle_deg(const Interval& chi);

// Corollary 10: measured by any p with τ(p, vᵢ) <= γ, arcsin(χ/γ²) <= θ <= 2 arccos(χ/γ²).
Interval ls_c10_min_angle_deg(const Interval& chi, const Interval& gamma);
Interval ls_c10_max_angle_deg(const Interval& chi, const Interval& gamma);

}  // namespace anisocert::theory
