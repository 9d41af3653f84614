#pragma once
// Relative distortion τ(p, q) = max(‖F_q F_p⁻¹‖₂, ‖F_p F_q⁻¹‖₂) (LS Proposition 1; BWY/LU's
// γ(p, q)). τ(p, q)² is the largest of the roots of det(M_q − λ M_p) = A λ² − B λ + C and of
// their inverses, with A = det M_p, C = det M_q, B = p11 q22 + p22 q11 − 2 p12 q12:
//   τ² = (B + √(B² − 4AC)) / (2 min(A, C)).

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

// Positive semi-definiteness of g·P − Q, entry by entry: sign(g p11 − q11), sign(g p22 − q22),
// sign((g p11 − q11)(g p22 − q22) − (g p12 − q12)²). Degrees 1/1/1 and 2/2/2 (g, P, Q).
struct ScaledDifferenceDiagonalKernel {
  static constexpr const char* name = "distortion (diagonal)";
  static constexpr std::size_t arity = 3;
  static constexpr std::array<int, arity> groups{2, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"gamma2", "P.mii", "Q.mii"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return x[0] * x[1] - x[2];
  }
};
struct ScaledDifferenceDeterminantKernel {
  static constexpr const char* name = "distortion (determinant)";
  static constexpr std::size_t arity = 7;
  static constexpr std::array<int, arity> groups{2, 1, 1, 1, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"gamma2", "P.m11", "P.m12", "P.m22",
                                                         "Q.m11",  "Q.m12", "Q.m22"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const T a = x[0] * x[1] - x[4], b = x[0] * x[2] - x[5], c = x[0] * x[3] - x[6];
    return a * c - b * b;
  }
};

// g·P − Q ⪰ 0 (a 2×2 symmetric matrix is PSD iff its diagonal and determinant are >= 0).
template <class S>
bool scaled_difference_psd(const S& g, const Sym2<S>& P, const Sym2<S>& Q) {
  require_finite<S>("distortion", {{"gamma2", g}, {"P.m11", P.m11}, {"P.m12", P.m12}, {"P.m22", P.m22},
                                {"Q.m11", Q.m11}, {"Q.m12", Q.m12}, {"Q.m22", Q.m22}});
  return filtered_sign<ScaledDifferenceDiagonalKernel>(std::array<S, 3>{g, P.m11, Q.m11}) != Sign::negative &&
         filtered_sign<ScaledDifferenceDiagonalKernel>(std::array<S, 3>{g, P.m22, Q.m22}) != Sign::negative &&
         filtered_sign<ScaledDifferenceDeterminantKernel>(
             std::array<S, 7>{g, P.m11, P.m12, P.m22, Q.m11, Q.m12, Q.m22}) != Sign::negative;
}

// τ(p, q) <= γ for γ² = gamma2 >= 0: γ²M_p − M_q ⪰ 0 and γ²M_q − M_p ⪰ 0 (CATALOG notation).
template <class S>
bool tau_at_most(const Sym2<S>& Mp, const Sym2<S>& Mq, const S& gamma2) {
  return scaled_difference_psd(gamma2, Mp, Mq) && scaled_difference_psd(gamma2, Mq, Mp);
}

// The 3×3 twin (issue 39; LU's γ between 3×3 metrics): a symmetric matrix is positive
// semi-definite iff every principal minor is >= 0 (Sylvester's criterion for semi-definiteness
// needs all seven, not the three leading ones: diag(0, −1, …) has leading minors 0, 0). The 1×1
// and 2×2 minors of g·P − Q are the kernels above on their entries; the 3×3 one is this, degree
// 3/3/3 (g, P, Q).
struct ScaledDifference3DeterminantKernel {
  static constexpr const char* name = "distortion (3×3 determinant)";
  static constexpr std::size_t arity = 13;
  static constexpr std::array<int, arity> groups{2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"gamma2", "P.m11", "P.m12", "P.m13", "P.m22", "P.m23", "P.m33",
                                                         "Q.m11",  "Q.m12", "Q.m13", "Q.m22", "Q.m23", "Q.m33"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const T a = x[0] * x[1] - x[7], b = x[0] * x[2] - x[8], c = x[0] * x[3] - x[9];
    const T d = x[0] * x[4] - x[10], e = x[0] * x[5] - x[11], f = x[0] * x[6] - x[12];
    return a * (d * f - e * e) - b * (b * f - e * c) + c * (b * e - d * c);
  }
};

template <class S>
bool scaled_difference_psd(const S& g, const Sym3<S>& P, const Sym3<S>& Q) {
  require_finite<S>("distortion", {{"gamma2", g}, {"P.m11", P.m11}, {"P.m12", P.m12}, {"P.m13", P.m13}, {"P.m22", P.m22},
                                {"P.m23", P.m23}, {"P.m33", P.m33}, {"Q.m11", Q.m11}, {"Q.m12", Q.m12}, {"Q.m13", Q.m13},
                                {"Q.m22", Q.m22}, {"Q.m23", Q.m23}, {"Q.m33", Q.m33}});
  const auto diagonal = [&](const S& p, const S& q) { return filtered_sign<ScaledDifferenceDiagonalKernel>(std::array<S, 3>{g, p, q}) != Sign::negative; };
  const auto minor = [&](const S& p11, const S& p12, const S& p22, const S& q11, const S& q12, const S& q22) {
    return filtered_sign<ScaledDifferenceDeterminantKernel>(std::array<S, 7>{g, p11, p12, p22, q11, q12, q22}) != Sign::negative;
  };
  return diagonal(P.m11, Q.m11) && diagonal(P.m22, Q.m22) && diagonal(P.m33, Q.m33) &&
         minor(P.m11, P.m12, P.m22, Q.m11, Q.m12, Q.m22) && minor(P.m11, P.m13, P.m33, Q.m11, Q.m13, Q.m33) &&
         minor(P.m22, P.m23, P.m33, Q.m22, Q.m23, Q.m33) &&
         filtered_sign<ScaledDifference3DeterminantKernel>(
             std::array<S, 13>{g, P.m11, P.m12, P.m13, P.m22, P.m23, P.m33, Q.m11, Q.m12, Q.m13, Q.m22, Q.m23, Q.m33}) != Sign::negative;
}

// γ(p, q) <= γ₀ for 3×3 metrics, γ₀² = gamma2: γ₀²M_p − M_q ⪰ 0 and γ₀²M_q − M_p ⪰ 0 (the
// generalized eigenvalues of M_q x = λ M_p x, and their inverses, at most γ₀²).
template <class S>
bool tau_at_most(const Sym3<S>& Mp, const Sym3<S>& Mq, const S& gamma2) {
  return scaled_difference_psd(gamma2, Mp, Mq) && scaled_difference_psd(gamma2, Mq, Mp);
}

// τ² as (B + √D) / m, D = B² − 4AC >= 0, m = 2 min(A, C) > 0: exact data of the quadratic
// irrational. The functions below need positive definite metrics and throw
// NotPositiveDefinite otherwise. (The double/rational sign predicates of this layer accept any
// symmetric matrices: they return the exact sign of their polynomial, and checking that a
// metric is positive definite is the job of whoever builds it, e.g. Metric2.)
struct TauSquared {
  Rational B, D, m;
};
TauSquared tau_squared(const Sym2<Rational>& Mp, const Sym2<Rational>& Mq);

// sign(τ(p, q) − τ(a, b)), exact.
Sign compare_tau(const Sym2<Rational>& Mp, const Sym2<Rational>& Mq, const Sym2<Rational>& Ma,
                 const Sym2<Rational>& Mb);

// sign(τ(p, q)² − g) for a rational g, exact (agrees with tau_at_most; a second code path).
Sign compare_tau_squared(const Sym2<Rational>& Mp, const Sym2<Rational>& Mq, const Rational& g);

}  // namespace anisocert::predicates
