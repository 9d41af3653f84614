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

// The 3×3 twin (issue 39): the generalized eigenvalues of Q x = λ P x are the eigenvalues of the
// symmetric C = L⁻¹ Q L⁻ᵀ, P = L Lᵀ (Cholesky); the largest by the trigonometric formula for a
// symmetric 3×3 matrix (doubles, well-conditioned in P's scale; a reported value, never a decision).
inline double largest_generalized_eigenvalue(const predicates::Sym3<double>& P, const predicates::Sym3<double>& Q) {
  const double l11 = std::sqrt(P.m11), l21 = P.m12 / l11, l31 = P.m13 / l11;
  const double l22 = std::sqrt(P.m22 - l21 * l21), l32 = (P.m23 - l31 * l21) / l22;
  const double l33 = std::sqrt(P.m33 - l31 * l31 - l32 * l32);
  // K = L⁻¹, lower triangular.
  const double k11 = 1 / l11, k22 = 1 / l22, k33 = 1 / l33, k21 = -l21 * k11 / l22, k32 = -l32 * k22 / l33;
  const double k31 = -(l31 * k11 + l32 * k21) / l33;
  const double K[3][3] = {{k11, 0, 0}, {k21, k22, 0}, {k31, k32, k33}};
  const double A[3][3] = {{Q.m11, Q.m12, Q.m13}, {Q.m12, Q.m22, Q.m23}, {Q.m13, Q.m23, Q.m33}};
  double KA[3][3] = {}, C[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) KA[i][j] += K[i][k] * A[k][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) C[i][j] += KA[i][k] * K[j][k];
  const double q = (C[0][0] + C[1][1] + C[2][2]) / 3;
  const double off = C[0][1] * C[0][1] + C[0][2] * C[0][2] + C[1][2] * C[1][2];
  const double p2 = (C[0][0] - q) * (C[0][0] - q) + (C[1][1] - q) * (C[1][1] - q) + (C[2][2] - q) * (C[2][2] - q) + 2 * off;
  if (!(p2 > 0)) return q;  // C = q I
  const double p = std::sqrt(p2 / 6);
  const double b00 = (C[0][0] - q) / p, b11 = (C[1][1] - q) / p, b22 = (C[2][2] - q) / p, b01 = C[0][1] / p, b02 = C[0][2] / p,
               b12 = C[1][2] / p;
  const double r = (b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02)) / 2;
  return q + 2 * p * std::cos(std::acos(std::clamp(r, -1.0, 1.0)) / 3);
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
