#pragma once
// The dihedral angle θ of tetrahedron abcd at its edge ab, between its faces abc and abd, measured
// by a metric M (issue 39; LU §3's slivers are the tetrahedra with a dihedral angle near 0° or
// 180°). With e = b − a, the face normals n_c = e × (c − a), n_d = e × (d − a), and A = adj(M),
// M's cofactor matrix:
//   cos θ = n_cᵀ A n_d / √(n_cᵀ A n_c · n_dᵀ A n_d).
// Euclidean (A = I): n_c·n_d = |e|² u_c·u_d for u_c, u_d the parts of c − a and d − a orthogonal to
// e, whose angle θ is. In a metric M = FᵀF, F maps the normals to det F · F⁻ᵀ n, which meet in
// det(M) · nᵀ M⁻¹ n' = nᵀ adj(M) n' (det M > 0 cancels in the quotient). Degrees: the coordinates 4,
// the metric 2 in n_cᵀ A n_d.

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

#include <utility>

namespace anisocert::predicates {

// (n_cᵀ A n_d, n_cᵀ A n_c · n_dᵀ A n_d) from a, b, c, d, M at x[0..17].
template <class T, std::size_t N>
constexpr std::pair<T, T> dihedral_dot_and_norms(const std::array<T, N>& x) {
  const T ex = x[3] - x[0], ey = x[4] - x[1], ez = x[5] - x[2];
  const T cx = x[6] - x[0], cy = x[7] - x[1], cz = x[8] - x[2];
  const T dx = x[9] - x[0], dy = x[10] - x[1], dz = x[11] - x[2];
  const T ncx = ey * cz - ez * cy, ncy = ez * cx - ex * cz, ncz = ex * cy - ey * cx;
  const T ndx = ey * dz - ez * dy, ndy = ez * dx - ex * dz, ndz = ex * dy - ey * dx;
  const T &m11 = x[12], &m12 = x[13], &m13 = x[14], &m22 = x[15], &m23 = x[16], &m33 = x[17];
  // adj(M), symmetric: the cofactors.
  const T a11 = m22 * m33 - m23 * m23, a12 = m13 * m23 - m12 * m33, a13 = m12 * m23 - m13 * m22;
  const T a22 = m11 * m33 - m13 * m13, a23 = m12 * m13 - m11 * m23, a33 = m11 * m22 - m12 * m12;
  const auto form = [&](const T& ux, const T& uy, const T& uz, const T& vx, const T& vy, const T& vz) {
    return T(ux * (a11 * vx + a12 * vy + a13 * vz) + uy * (a12 * vx + a22 * vy + a23 * vz) + uz * (a13 * vx + a23 * vy + a33 * vz));
  };
  return {form(ncx, ncy, ncz, ndx, ndy, ndz), T(form(ncx, ncy, ncz, ncx, ncy, ncz) * form(ndx, ndy, ndz, ndx, ndy, ndz))};
}

inline constexpr std::array<const char*, 19> dihedral_inputs{"a.x", "a.y", "a.z", "b.x", "b.y", "b.z", "c.x", "c.y", "c.z", "d.x",
                                                             "d.y", "d.z", "M.m11", "M.m12", "M.m13", "M.m22", "M.m23", "M.m33", "bound"};
inline constexpr std::array<int, 19> dihedral_groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 2};
inline constexpr std::array<int, 19> dihedral_origin{0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, -1, -1, -1, -1, -1, -1, -1};

// n_cᵀ adj(M) n_d: positive when θ is acute, zero when right, negative when obtuse.
struct DihedralDotKernel {
  static constexpr const char* name = "dihedral angle's cosine sign";
  static constexpr std::size_t arity = 18;
  static constexpr auto groups = [] {
    std::array<int, arity> g{};
    for (std::size_t i = 0; i < arity; ++i) g[i] = dihedral_groups[i];
    return g;
  }();
  static constexpr auto inputs = [] {
    std::array<const char*, arity> n{};
    for (std::size_t i = 0; i < arity; ++i) n[i] = dihedral_inputs[i];
    return n;
  }();
  static constexpr auto origin = [] {
    std::array<int, arity> o{};
    for (std::size_t i = 0; i < arity; ++i) o[i] = dihedral_origin[i];
    return o;
  }();
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return dihedral_dot_and_norms(x).first;
  }
};

// (n_cᵀ A n_d)² − (1 − s²) · n_cᵀ A n_c · n_dᵀ A n_d = norms · (cos²θ − 1 + s²): for an acute θ,
// sign(s² − sin²θ), positive when θ < arcsin s. Degree 8 in the coordinates, 4 in the metric: beyond
// the static filter's range guard (filtered_sign.hpp, total degree 8), so it is decided by the
// interval stage, then exactly (interval_then_exact).
struct DihedralSinKernel {
  static constexpr const char* name = "dihedral angle against sin² bound";
  static constexpr std::size_t arity = 19;
  static constexpr auto groups = dihedral_groups;
  static constexpr auto inputs = dihedral_inputs;
  static constexpr auto origin = dihedral_origin;
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const auto [dot, norms] = dihedral_dot_and_norms(x);
    return dot * dot - norms + x[18] * norms;
  }
};

}  // namespace anisocert::predicates
