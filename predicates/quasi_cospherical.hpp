#pragma once
// γ₀-cosphericity of five points for a metric M (LU Definition 3.6 and Lemma 3.7, the
// configurations Definition 3.9 measures and LU's sliver removal avoids): whether there are
// metrics N, N′ with γ(M, N), γ(M, N′), γ(N, N′) <= γ₀ for which e is strictly outside the
// N-circumsphere of abcd and strictly inside the N′-one.
//
// Decided exactly by three facts.
//  1. The lifted in-sphere determinant is linear in the metric (its lift x ↦ xᵀNx fills one
//     column): insphere_N(a, b, c, d; e) = ⟨G, N⟩ = tr(GN), with, for u = a − e, …, d − e and
//     the minors of insphere.hpp, G = bcd·uuᵀ − acd·vvᵀ + abd·wwᵀ − abc·zzᵀ (so ⟨G, M⟩ is
//     exactly InSphereKernel's value).
//  2. γ(M, N) <= γ₀ (BWY Definition 2.1's distortion, predicates/distortion.hpp) iff
//     Ñ = F⁻ᵀ N F⁻¹ (M = FᵀF) has its spectrum in [γ₀⁻², γ₀²], a convex set B containing M.
//     So a pair (N, N′) exists iff some N ∈ B has ⟨G, N⟩ of the opposite strict sign to
//     ⟨G, M⟩ (take N′ = M; conversely one of N, N′ is opposite to M), or ⟨G, M⟩ = 0 and G ≠ 0.
//  3. With H = F G Fᵀ (the eigenvalues of GM: h₁ >= h₂ >= h₃), min over B of ⟨H, Ñ⟩ is
//     γ₀⁻² Σ_{h>0} h + γ₀² Σ_{h<0} h (the spectra paired in opposite order, von Neumann's trace
//     inequality). With the sign of G chosen so that c₁ = tr(GM) > 0, and c₂, c₃ the other
//     coefficients of det(x − GM) = x³ − c₁x² + c₂x − c₃, k = γ₀⁴ − 1:
//       one negative eigenvalue (c₃ < 0, or c₃ = 0 < −c₂): the minimum is negative iff
//         h₃ < −c₁/k, i.e. A = c₁³(1 + k) + c₁c₂k² + c₃k³ < 0 (k³ χ(−c₁/k) = −A);
//       two negative eigenvalues (c₂ < 0 < c₃): iff h₁ > c₁(1 + k)/k, i.e.
//         B = c₁³(1 + k)² + c₁c₂k²(1 + k) − c₃k³ < 0 (k³ χ(c₁(1 + k)/k) = B);
//       none: never (the minimum is γ₀⁻² c₁ > 0).
//     The count of negative eigenvalues is exact by Descartes' rule on x³ + c₁x² + c₂x + c₃ (all
//     roots real: GM is similar to the symmetric H). A zero A or B: the minimum is exactly 0, a
//     tie at this γ₀.
// The critical distortion γ* = (Σ_{h>0} h / −Σ_{h<0} h)^(1/4) (with c₁ > 0; 1 when c₁ = 0) is the
// least γ₀ for which the five are γ₀-cospherical: the measure the certifier reports.
//
// Kernels: degree 5 in the coordinates per factor of G, each one eval<T>; inputs a, b, c, d, e,
// then M (m11 m12 m13 m22 m23 m33), then k.

#include "predicates/filtered_sign.hpp"
#include "predicates/insphere.hpp"
#include "predicates/point.hpp"

#include <cmath>
#include <type_traits>

namespace anisocert::predicates {

// G of fact 1, its six entries g11 g12 g13 g22 g23 g33, from the 15 coordinates.
template <class T>
constexpr std::array<T, 6> lifted_gram(const std::array<T, 15>& x) {
  const T ax = x[0] - x[12], ay = x[1] - x[13], az = x[2] - x[14];
  const T bx = x[3] - x[12], by = x[4] - x[13], bz = x[5] - x[14];
  const T cx = x[6] - x[12], cy = x[7] - x[13], cz = x[8] - x[14];
  const T dx = x[9] - x[12], dy = x[10] - x[13], dz = x[11] - x[14];
  const T ab = ax * by - ay * bx, ac = ax * cy - ay * cx, ad = ax * dy - ay * dx;
  const T bc = bx * cy - by * cx, bd = bx * dy - by * dx, cd = cx * dy - cy * dx;
  const std::array<T, 4> w{T(bz * cd - cz * bd + dz * bc), T(-(az * cd - cz * ad + dz * ac)), T(az * bd - bz * ad + dz * ab),
                           T(-(az * bc - bz * ac + cz * ab))};
  const std::array<std::array<T, 3>, 4> u{{{ax, ay, az}, {bx, by, bz}, {cx, cy, cz}, {dx, dy, dz}}};
  std::array<T, 6> g;
  const std::array<std::pair<int, int>, 6> entry{{{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}}};
  for (std::size_t k = 0; k < 6; ++k) {
    const auto [i, j] = entry[k];
    g[k] = (w[0] * u[0][i] * u[0][j] + w[1] * u[1][i] * u[1][j]) + (w[2] * u[2][i] * u[2][j] + w[3] * u[3][i] * u[3][j]);
  }
  return g;
}

// c₂ and c₃ of det(x − GM) (c₁ = tr GM is InSphereKernel's value): the sum of GM's principal
// 2 × 2 minors, and det G · det M.
template <class T>
constexpr std::pair<T, T> lifted_gram_invariants(const std::array<T, 21>& x) {
  std::array<T, 15> p;
  for (std::size_t i = 0; i < 15; ++i) p[i] = x[i];
  const auto g = lifted_gram(p);
  const std::array<std::array<T, 3>, 3> G{{{g[0], g[1], g[2]}, {g[1], g[3], g[4]}, {g[2], g[4], g[5]}}};
  const std::array<std::array<T, 3>, 3> M{{{x[15], x[16], x[17]}, {x[16], x[18], x[19]}, {x[17], x[19], x[20]}}};
  std::array<std::array<T, 3>, 3> P;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) P[i][j] = G[i][0] * M[0][j] + G[i][1] * M[1][j] + G[i][2] * M[2][j];
  const T c2 = (P[0][0] * P[1][1] - P[0][1] * P[1][0]) + (P[0][0] * P[2][2] - P[0][2] * P[2][0]) + (P[1][1] * P[2][2] - P[1][2] * P[2][1]);
  const auto det = [](const std::array<std::array<T, 3>, 3>& m) {
    return T(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
  };
  return {c2, T(det(G) * det(M))};
}

inline constexpr std::array<int, 21> cospherical_groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
inline constexpr std::array<const char*, 22> cospherical_inputs{"a.x", "a.y", "a.z", "b.x",   "b.y",   "b.z",   "c.x",   "c.y",
                                                                "c.z", "d.x", "d.y", "d.z",   "e.x",   "e.y",   "e.z",   "M.m11",
                                                                "M.m12", "M.m13", "M.m22", "M.m23", "M.m33", "k"};

// c₂ (its sign with c₃'s counts the negative eigenvalues).
struct LiftedGramSecondKernel {
  static constexpr const char* name = "quasi-cosphericity (c2)";
  static constexpr std::size_t arity = 21;
  static constexpr std::array<int, arity> groups = cospherical_groups;
  static constexpr std::array<const char*, arity> inputs = [] {
    std::array<const char*, arity> n{};
    for (std::size_t i = 0; i < arity; ++i) n[i] = cospherical_inputs[i];
    return n;
  }();
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return lifted_gram_invariants(x).first;
  }
};

// c₃ = det G · det M.
struct LiftedGramThirdKernel {
  static constexpr const char* name = "quasi-cosphericity (c3)";
  static constexpr std::size_t arity = 21;
  static constexpr std::array<int, arity> groups = cospherical_groups;
  static constexpr std::array<const char*, arity> inputs = LiftedGramSecondKernel::inputs;
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return lifted_gram_invariants(x).second;
  }
};

template <class T>
constexpr std::array<T, 21> without_k(const std::array<T, 22>& x) {
  std::array<T, 21> y;
  for (std::size_t i = 0; i < 21; ++i) y[i] = x[i];
  return y;
}

// A = c₁³(1 + k) + c₁c₂k² + c₃k³ and B = c₁³(1 + k)² + c₁c₂k²(1 + k) − c₃k³ from the invariants
// (the kernels below, and enclosures of them computed once for both).
template <class T>
constexpr T one_negative_polynomial(const T& c1, const T& c2, const T& c3, const T& k) {
  const T c1c1c1 = c1 * c1 * c1, kk = k * k;
  return (c1c1c1 + c1c1c1 * k) + (c1 * c2 * kk + c3 * kk * k);
}
template <class T>
constexpr T two_negative_polynomial(const T& c1, const T& c2, const T& c3, const T& k) {
  const T c1c1c1 = c1 * c1 * c1, kk = k * k, c1c2kk = c1 * c2 * kk;
  return ((c1c1c1 + T(2) * c1c1c1 * k) + c1c1c1 * kk) + ((c1c2kk + c1c2kk * k) - c3 * kk * k);
}

// A (`two` false: one negative eigenvalue) or B (two), from the configuration and k.
template <bool two>
struct CosphericalDecisionKernel {
  static constexpr const char* name = two ? "quasi-cosphericity (two negative eigenvalues)" : "quasi-cosphericity (one negative eigenvalue)";
  static constexpr std::size_t arity = 22;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 2};
  static constexpr std::array<const char*, arity> inputs = cospherical_inputs;
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const auto y = without_k(x);
    const T c1 = InSphereKernel::eval(y);
    const auto [c2, c3] = lifted_gram_invariants(y);
    return two ? two_negative_polynomial(c1, c2, c3, x[21]) : one_negative_polynomial(c1, c2, c3, x[21]);
  }
};
using CosphericalOneNegativeKernel = CosphericalDecisionKernel<false>;
using CosphericalTwoNegativeKernel = CosphericalDecisionKernel<true>;

// The verdict of fact 3 from the signs of its polynomials, each computed by `sign_of(kernel)`:
// positive when the five are strictly γ₀-cospherical for M, zero at the boundary (a zero A or B,
// or G = 0: the five are coplanar), negative when they are not.
template <class SignOf>
Sign quasi_cospherical_from(SignOf&& sign_of) {
  const Sign s1 = sign_of(InSphereKernel{});
  const Sign s2 = sign_of(LiftedGramSecondKernel{});
  const Sign s3 = s1 * sign_of(LiftedGramThirdKernel{});  // c₃ after choosing c₁ > 0 (it flips with G)
  if (s1 == Sign::zero) {
    // e on the M-sphere: strictly both sides within any γ₀ > 1 unless G = 0 (then ⟨G, N⟩ = 0 for
    // all N, and c₂ = c₃ = 0; G ≠ 0 with c₁ = 0 has eigenvalues of both signs or c₂ < 0).
    return s2 == Sign::zero && s3 == Sign::zero ? Sign::zero : Sign::positive;
  }
  const bool two_negative = s2 == Sign::negative && s3 == Sign::positive;
  const bool one_negative = s3 == Sign::negative || (s3 == Sign::zero && s2 == Sign::negative);
  if (!two_negative && !one_negative) return Sign::negative;
  const Sign decision = two_negative ? sign_of(CosphericalTwoNegativeKernel{}) : sign_of(CosphericalOneNegativeKernel{});
  return -(s1 * decision);  // A, B after choosing c₁ > 0 (both flip with G); < 0: cospherical
}

// k = γ₀⁴ − 1 > 0 (γ₀ > 1). Throws NonFiniteInput for a NaN or an infinity among double inputs.
template <class S>
Sign quasi_cospherical(const Point3<S>& a, const Point3<S>& b, const Point3<S>& c, const Point3<S>& d, const Point3<S>& e,
                       const Sym3<S>& M, const S& k) {
  const std::array<S, 22> x{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z, M.m11, M.m12, M.m13, M.m22, M.m23, M.m33, k};
  if constexpr (std::is_same_v<S, double>)
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!std::isfinite(x[i])) throw_non_finite("quasi-cosphericity", cospherical_inputs[i], x[i]);
  return quasi_cospherical_from([&]<class K>(K) {
    std::array<S, K::arity> y;
    for (std::size_t i = 0; i < K::arity; ++i) y[i] = x[i];
    return high_degree_sign<K>(y);  // degrees up to 21 (filtered_sign.hpp)
  });
}

}  // namespace anisocert::predicates
