#pragma once
// The circumellipsoid of a tetrahedron abcd in a metric M (LU §3: the circumsphere of a simplex for
// the distance d_M of its vertex; LU Definition 3.10's radius-edge ratio is its radius over the
// shortest edge), the 3D twin of circumellipse.hpp: its centre a + x where
//   2 (q − a)ᵀ M x = (q − a)ᵀ M (q − a),  q = b, c, d,
// solved by Cramer's rule, and r² = xᵀ M x. One construction for every number type T as there:
// FilterInterval (an interval divisor containing 0 gives the whole line) and Rational (a flat
// tetrahedron divides by zero: callers test orientation first).
#include "predicates/point.hpp"

#include <array>

namespace anisocert::geometry {

template <class T>
struct Circumellipsoid {
  std::array<T, 3> x;  // the centre minus a
  T r2;                // the squared M-radius
};

// Cramer's determinants of the centre: x_k = numerator[k] / denominator, polynomials in the
// coordinates (differences from a) and M: degrees 4 and 3 in the coordinates, 3 in the metric
// (so that a certifier can enclose them by a static filter's bound, predicates::static_enclosure).
template <class T>
struct CramerDeterminants {
  std::array<T, 3> numerator;
  T denominator;
};

template <class T>
constexpr CramerDeterminants<T> circumcentre_determinants(const predicates::Point3<T>& a, const predicates::Point3<T>& b,
                                                          const predicates::Point3<T>& c, const predicates::Point3<T>& d,
                                                          const predicates::Sym3<T>& M) {
  const auto times = [&](const std::array<T, 3>& v) {
    return std::array<T, 3>{M.m11 * v[0] + M.m12 * v[1] + M.m13 * v[2], M.m12 * v[0] + M.m22 * v[1] + M.m23 * v[2],
                            M.m13 * v[0] + M.m23 * v[1] + M.m33 * v[2]};
  };
  const auto det3 = [](const std::array<std::array<T, 3>, 3>& m) {
    return T(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
  };
  std::array<std::array<T, 3>, 3> A;
  std::array<T, 3> rhs;
  const std::array<const predicates::Point3<T>*, 3> q{&b, &c, &d};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::array<T, 3> e{T(q[i]->x - a.x), T(q[i]->y - a.y), T(q[i]->z - a.z)};
    const auto Me = times(e);
    A[i] = {T(Me[0] * T(2)), T(Me[1] * T(2)), T(Me[2] * T(2))};
    rhs[i] = e[0] * Me[0] + e[1] * Me[1] + e[2] * Me[2];
  }
  CramerDeterminants<T> r;
  r.denominator = det3(A);
  for (std::size_t k = 0; k < 3; ++k) {
    auto Ak = A;
    for (std::size_t i = 0; i < 3; ++i) Ak[i][k] = rhs[i];
    r.numerator[k] = det3(Ak);
  }
  return r;
}

// The ellipsoid from the determinants (or enclosures of them).
template <class T>
Circumellipsoid<T> circumellipsoid_of(const CramerDeterminants<T>& c, const predicates::Sym3<T>& M) {
  Circumellipsoid<T> r;
  for (std::size_t k = 0; k < 3; ++k) r.x[k] = c.numerator[k] / c.denominator;
  const std::array<T, 3> Mx{M.m11 * r.x[0] + M.m12 * r.x[1] + M.m13 * r.x[2], M.m12 * r.x[0] + M.m22 * r.x[1] + M.m23 * r.x[2],
                            M.m13 * r.x[0] + M.m23 * r.x[1] + M.m33 * r.x[2]};
  r.r2 = r.x[0] * Mx[0] + r.x[1] * Mx[1] + r.x[2] * Mx[2];
  return r;
}

template <class T>
Circumellipsoid<T> circumellipsoid(const predicates::Point3<T>& a, const predicates::Point3<T>& b, const predicates::Point3<T>& c,
                                   const predicates::Point3<T>& d, const predicates::Sym3<T>& M) {
  return circumellipsoid_of(circumcentre_determinants(a, b, c, d, M), M);
}

}  // namespace anisocert::geometry
