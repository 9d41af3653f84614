#pragma once
// LU Definition 3.16 in dimension 3 (issue 40: rule (1), encroachment of a boundary facet and of
// a boundary edge): p encroaches an edge ab, or a facet abc, for the metric M when p lies strictly
// inside its diametral M-ball, the smallest M-ball through its vertices (for a facet, centred in
// its plane). On the sphere: not encroaching (the Gabriel tie).
//  - Edge: (a − p)ᵀ M (b − p) < 0, the M-angle apb obtuse (MetricDot3Kernel; encroachment.hpp's
//    twin). Degree 2 in the coordinates, 1 in the metric.
//  - Facet: with u = b − a, v = c − a, w = p − a, A = uᵀMu, B = uᵀMv, C = vᵀMv and D = AC − B²
//    (> 0 unless a, b, c are collinear), the centre is a + αu + βv with (α, β) = (C(A − B),
//    A(C − B)) / 2D (equidistant from a, b, c in M), so
//      P = D·wᵀMw − C(A − B)·wᵀMu − A(C − B)·wᵀMv = D · (Q(p − centre) − Q(a − centre)),
//    negative when p is strictly inside. Degree 6 in the coordinates, 3 in the metric: a total
//    of 9, beyond the static stage's range guard, so its sign takes the later stages
//    (filtered_sign.hpp `high_degree_sign`).

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

// (p − o)ᵀ M (r − o) in dimension 3.
struct MetricDot3Kernel {
  static constexpr const char* name = "metric inner product (3D)";
  static constexpr std::size_t arity = 15;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"p.x", "p.y", "p.z", "o.x", "o.y", "o.z", "r.x", "r.y",
                                                         "r.z", "M.m11", "M.m12", "M.m13", "M.m22", "M.m23", "M.m33"};
  static constexpr std::array<int, arity> origin{3, 4, 5, 3, 4, 5, 3, 4, 5, -1, -1, -1, -1, -1, -1};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const Sym3<T> M{x[9], x[10], x[11], x[12], x[13], x[14]};
    return bilinear_form(M, T(x[0] - x[3]), T(x[1] - x[4]), T(x[2] - x[5]), T(x[6] - x[3]), T(x[7] - x[4]), T(x[8] - x[5]));
  }
};

// D (Q(p − centre) − Q(a − centre)) for the diametral M-sphere of the facet abc (above).
struct DiametralSphereKernel {
  static constexpr const char* name = "diametral sphere of a facet";
  static constexpr std::size_t arity = 18;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"p.x", "p.y", "p.z", "a.x", "a.y", "a.z", "b.x", "b.y", "b.z",
                                                         "c.x", "c.y", "c.z", "M.m11", "M.m12", "M.m13", "M.m22", "M.m23", "M.m33"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const Sym3<T> M{x[12], x[13], x[14], x[15], x[16], x[17]};
    const T wx = x[0] - x[3], wy = x[1] - x[4], wz = x[2] - x[5];
    const T ux = x[6] - x[3], uy = x[7] - x[4], uz = x[8] - x[5];
    const T vx = x[9] - x[3], vy = x[10] - x[4], vz = x[11] - x[5];
    const T A = quadratic_form(M, ux, uy, uz), B = bilinear_form(M, ux, uy, uz, vx, vy, vz), C = quadratic_form(M, vx, vy, vz);
    const T D = A * C - B * B;
    return D * quadratic_form(M, wx, wy, wz) - C * (A - B) * bilinear_form(M, wx, wy, wz, ux, uy, uz) -
           A * (C - B) * bilinear_form(M, wx, wy, wz, vx, vy, vz);
  }
};

// p strictly inside the diametral M-ball of the edge ab.
template <class S>
bool encroaches_edge(const Point3<S>& p, const Point3<S>& a, const Point3<S>& b, const Sym3<S>& M) {
  return filtered_sign<MetricDot3Kernel>(std::array<S, 15>{a.x, a.y, a.z, p.x, p.y, p.z, b.x, b.y, b.z, M.m11, M.m12, M.m13, M.m22, M.m23, M.m33}) ==
         Sign::negative;
}

// p strictly inside the diametral M-ball of the facet abc (a, b, c not collinear).
template <class S>
bool encroaches_facet(const Point3<S>& p, const Point3<S>& a, const Point3<S>& b, const Point3<S>& c, const Sym3<S>& M) {
  return high_degree_sign<DiametralSphereKernel>(std::array<S, 18>{p.x, p.y, p.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, M.m11, M.m12,
                                                                M.m13, M.m22, M.m23, M.m33}) == Sign::negative;
}

}  // namespace anisocert::predicates
