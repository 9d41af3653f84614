#pragma once
// The relative distortion τ(P, Q)² (LS Proposition 1; BWY/LU's γ(p, q)²), computed, not decided:
// the largest root λ of det(Q − λP) = A λ² − B λ + C (A = det P, C = det Q,
// B = p11 q22 + p22 q11 − 2 p12 q12) and of its reverse det(P − λQ), i.e.
//   τ² = max((B + √(B² − 4AC)) / 2A, (B + √(B² − 4AC)) / 2C).
// One construction for every number type T with +, −, ·, /, sqrt and max (the refiners' estimates
// and the certifier's reported worst value are doubles). The decisions "τ ≤ γ" are exact
// predicates (predicates/distortion.hpp), never this.
// (B² − 4AC ≥ 0 always; a negative rounded value is read as 0. Near τ = 1 it cancels, and the
// estimate is good to about √ε ≈ 10⁻⁸ relative there, to 10⁻⁹ (tested) away from it:
// DistortionEstimate.AgreesWithTheExactComparison.)
#include "predicates/point.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::geometry {

// The largest generalized eigenvalue λ of Q x = λ P x.
template <class T>
[[gnu::always_inline]] inline T largest_generalized_eigenvalue(const predicates::Sym2<T>& P, const predicates::Sym2<T>& Q) {
  using std::max;
  using std::sqrt;
  const T a2 = P.m11 * P.m22 - P.m12 * P.m12, b1 = -(P.m11 * Q.m22 + P.m22 * Q.m11 - 2 * P.m12 * Q.m12),
          c0 = Q.m11 * Q.m22 - Q.m12 * Q.m12;
  return (-b1 + sqrt(max(T(0), b1 * b1 - 4 * a2 * c0))) / (2 * a2);
}

template <class T>
T tau_squared_estimate(const predicates::Sym2<T>& P, const predicates::Sym2<T>& Q) {
  using std::max;
  return max(largest_generalized_eigenvalue(P, Q), largest_generalized_eigenvalue(Q, P));
}

// The 3×3 twin (issue 39): the generalized eigenvalues of Q x = λ P x are the roots of
// det(Q − λP) = −(a λ³ − b λ² + c λ − d), a = det P, d = det Q, b and c the mixed terms; all real and
// positive for positive definite P, Q, found by the trigonometric formula for a cubic with three
// real roots (doubles; a reported value, never a decision).
inline double largest_generalized_eigenvalue(const predicates::Sym3<double>& P, const predicates::Sym3<double>& Q) {
  const auto det = [](const predicates::Sym3<double>& M) {
    return M.m11 * (M.m22 * M.m33 - M.m23 * M.m23) - M.m12 * (M.m12 * M.m33 - M.m23 * M.m13) + M.m13 * (M.m12 * M.m23 - M.m22 * M.m13);
  };
  // det(Q − λP) at λ = 0, ±1, 2 gives the cubic's coefficients exactly as a polynomial identity.
  const auto at = [&](double l) {
    return det({Q.m11 - l * P.m11, Q.m12 - l * P.m12, Q.m13 - l * P.m13, Q.m22 - l * P.m22, Q.m23 - l * P.m23, Q.m33 - l * P.m33});
  };
  const double f0 = at(0), f1 = at(1), fm = at(-1), f2 = at(2);
  // f(λ) = k3 λ³ + k2 λ² + k1 λ + k0.
  const double k0 = f0, k2 = (f1 + fm) / 2 - f0, k3 = (f2 - 2 * f1 + f0 - 2 * k2) / 6, k1 = f1 - f0 - k2 - k3;
  // λ³ + B λ² + C λ + D = 0, depressed by λ = y − B/3: y³ + p y + q = 0.
  const double B = k2 / k3, C = k1 / k3, D = k0 / k3;
  const double p = C - B * B / 3, q = 2 * B * B * B / 27 - B * C / 3 + D;
  if (p >= 0) return -B / 3;  // a triple root (P and Q proportional), up to rounding
  const double m = 2 * std::sqrt(-p / 3), theta = std::acos(std::clamp(3 * q / (p * m), -1.0, 1.0)) / 3;
  return m * std::cos(theta) - B / 3;  // the largest of m cos(θ − 2πk/3) − B/3
}

inline double tau_squared_estimate(const predicates::Sym3<double>& P, const predicates::Sym3<double>& Q) {
  return std::max(largest_generalized_eigenvalue(P, Q), largest_generalized_eigenvalue(Q, P));
}

// τ² < g2 for each pair of three metrics (a triangle's vertices'), estimated.
template <class T>
bool pairwise_tau_squared_below(const predicates::Sym2<T>& A, const predicates::Sym2<T>& B, const predicates::Sym2<T>& C,
                                const T& g2) {
  return tau_squared_estimate(A, B) < g2 && tau_squared_estimate(A, C) < g2 && tau_squared_estimate(B, C) < g2;
}

}  // namespace anisocert::geometry
