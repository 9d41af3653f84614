#pragma once
// Points and symmetric matrices over a scalar type S: double (a double denotes the rational it
// is) or Rational. Predicates accept either; constructions are exact (Rational).

namespace anisocert::predicates {

template <class S>
struct Point2 {
  S x, y;
};

// [m11 m12; m12 m22], the DESIGN.md order [m11, m12, m22].
template <class S>
struct Sym2 {
  S m11, m12, m22;
  friend bool operator==(const Sym2&, const Sym2&) = default;
};

template <class S>
struct Point3 {
  S x, y, z;
};

// [m11 m12 m13; m12 m22 m23; m13 m23 m33].
template <class S>
struct Sym3 {
  S m11, m12, m13, m22, m23, m33;
  friend bool operator==(const Sym3&, const Sym3&) = default;
};

// (dx, dy) M (dx, dy)ᵀ, the squared length of (dx, dy) measured by M (LS §2: d_p(a, b)²).
template <class T>
constexpr T quadratic_form(const T& m11, const T& m12, const T& m22, const T& dx, const T& dy) {
  return dx * (m11 * dx + m12 * dy) + dy * (m12 * dx + m22 * dy);
}

template <class T>
constexpr T quadratic_form(const Sym2<T>& M, const T& dx, const T& dy) {
  return quadratic_form(M.m11, M.m12, M.m22, dx, dy);
}

// (dx, dy, dz) M (dx, dy, dz)ᵀ, the squared length of a vector measured by a 3×3 metric (LU §2).
template <class T>
constexpr T quadratic_form(const T& m11, const T& m12, const T& m13, const T& m22, const T& m23, const T& m33, const T& dx,
                           const T& dy, const T& dz) {
  return dx * (m11 * dx + m12 * dy + m13 * dz) + dy * (m12 * dx + m22 * dy + m23 * dz) + dz * (m13 * dx + m23 * dy + m33 * dz);
}

template <class T>
constexpr T quadratic_form(const Sym3<T>& M, const T& dx, const T& dy, const T& dz) {
  return quadratic_form(M.m11, M.m12, M.m13, M.m22, M.m23, M.m33, dx, dy, dz);
}

// (ax, ay) M (bx, by)ᵀ, the M-inner product.
template <class T>
constexpr T bilinear_form(const T& m11, const T& m12, const T& m22, const T& ax, const T& ay, const T& bx, const T& by) {
  return ax * (m11 * bx + m12 * by) + ay * (m12 * bx + m22 * by);
}

// (ax, ay, az) M (bx, by, bz)ᵀ, the M-inner product in dimension 3.
template <class T>
constexpr T bilinear_form(const Sym3<T>& M, const T& ax, const T& ay, const T& az, const T& bx, const T& by, const T& bz) {
  return ax * (M.m11 * bx + M.m12 * by + M.m13 * bz) + ay * (M.m12 * bx + M.m22 * by + M.m23 * bz) + az * (M.m13 * bx + M.m23 * by + M.m33 * bz);
}

}  // namespace anisocert::predicates
