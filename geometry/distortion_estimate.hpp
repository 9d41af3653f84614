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

// τ² < g2 for each pair of three metrics (a triangle's vertices'), estimated.
template <class T>
bool pairwise_tau_squared_below(const predicates::Sym2<T>& A, const predicates::Sym2<T>& B, const predicates::Sym2<T>& C,
                                const T& g2) {
  return tau_squared_estimate(A, B) < g2 && tau_squared_estimate(A, C) < g2 && tau_squared_estimate(B, C) < g2;
}

}  // namespace anisocert::geometry
