#pragma once
// BWY Lemma 1 (power-diagram lifting), for d = 2 and d = 3: x̂ = (x, x_r x_s for r <= s) in
// R^D, D = d(d+3)/2; the sphere σ(p) has centre p̂ = (M p, q) with q^{rr} = −M^{rr}/2,
// q^{rs} = −M^{rs} (r < s), and squared radius ‖p̂‖² − pᵀMp. The anisotropic Voronoi diagram
// is the power diagram of the σ(pᵢ) restricted to {x̂}, by the identity
//   power(x̂, σ(p)) = ‖x̂ − p̂‖² − radius² = ‖x̂‖² + d_p(x)².
// Exact constructions over the rationals; a metric is given by its upper triangle, row by
// row: (m11, m12, m22) for d = 2, (m11, m12, m13, m22, m23, m33) for d = 3.

#include "numbers/rational.hpp"

#include <array>

namespace anisocert::predicates {

template <int d>
inline constexpr int lifted_dimension = d * (d + 3) / 2;

template <int d>
using Vec = std::array<Rational, d>;
template <int d>
using Upper = std::array<Rational, d*(d + 1) / 2>;  // the metric's upper triangle, row by row

template <int d>
struct LiftedSphere {
  Vec<lifted_dimension<d>> centre;
  Rational radius2;
};

namespace detail {
template <int d>
int upper_index(int r, int s) {  // r <= s
  return r * d - r * (r - 1) / 2 + (s - r);
}
template <int d>
Rational entry(const Upper<d>& M, int r, int s) {
  return r <= s ? M[upper_index<d>(r, s)] : M[upper_index<d>(s, r)];
}
}  // namespace detail

// x̂ = (x₁..x_d, x_r x_s for r <= s in the order of the upper triangle).
template <int d>
Vec<lifted_dimension<d>> lift(const Vec<d>& x) {
  Vec<lifted_dimension<d>> h;
  for (int r = 0; r < d; ++r) h[r] = x[r];
  for (int r = 0; r < d; ++r)
    for (int s = r; s < d; ++s) h[d + detail::upper_index<d>(r, s)] = x[r] * x[s];
  return h;
}

template <int d>
LiftedSphere<d> lifted_sphere(const Vec<d>& p, const Upper<d>& M) {
  LiftedSphere<d> sigma;
  Rational pMp = 0;
  for (int r = 0; r < d; ++r) {
    Rational Mp = 0;
    for (int s = 0; s < d; ++s) Mp += detail::entry<d>(M, r, s) * p[s];
    sigma.centre[r] = Mp;
    pMp += p[r] * Mp;
  }
  for (int r = 0; r < d; ++r)
    for (int s = r; s < d; ++s)
      sigma.centre[d + detail::upper_index<d>(r, s)] =
          r == s ? Rational(-detail::entry<d>(M, r, r) / 2) : Rational(-detail::entry<d>(M, r, s));
  Rational norm2 = 0;
  for (const Rational& c : sigma.centre) norm2 += c * c;
  sigma.radius2 = norm2 - pMp;
  return sigma;
}

// power(x̂, σ) = ‖x̂ − centre‖² − radius².
template <int d>
Rational power(const Vec<lifted_dimension<d>>& xhat, const LiftedSphere<d>& sigma) {
  Rational s = 0;
  for (int i = 0; i < lifted_dimension<d>; ++i) s += (xhat[i] - sigma.centre[i]) * (xhat[i] - sigma.centre[i]);
  return s - sigma.radius2;
}

}  // namespace anisocert::predicates
