#pragma once
// The bounding box of the M-ball {p : (p − c)ᵀ M (p − c) ≤ r²}: half-widths
//   hx = √(r² m22 / det M),  hy = √(r² m11 / det M)
// (the extent of the ellipse along each axis: max of eₓᵀp over the ball is r √((M⁻¹)₁₁)).
// One construction for double and FilterInterval (sqrt and / of the type; for an interval the
// upper ends bound the true half-widths).
#include "predicates/point.hpp"

#include <cmath>

namespace anisocert::geometry {

template <class T>
struct HalfWidths {
  T hx, hy;
};

template <class T>
HalfWidths<T> ellipse_half_widths(const predicates::Sym2<T>& M, const T& r2) {
  using std::sqrt;
  const T det = M.m11 * M.m22 - M.m12 * M.m12;
  return {sqrt(r2 * M.m22 / det), sqrt(r2 * M.m11 / det)};
}

// Its 3D twin (the M-ellipsoid's box, issue 40's refiner): half-widths √(r² (M⁻¹)ᵢᵢ), the
// diagonal of M⁻¹ as cofactors over det M.
template <class T>
struct HalfWidths3 {
  T hx, hy, hz;
};

template <class T>
HalfWidths3<T> ellipsoid_half_widths(const predicates::Sym3<T>& M, const T& r2) {
  using std::sqrt;
  const T c11 = M.m22 * M.m33 - M.m23 * M.m23, c22 = M.m11 * M.m33 - M.m13 * M.m13, c33 = M.m11 * M.m22 - M.m12 * M.m12;
  const T det = M.m11 * c11 - M.m12 * (M.m12 * M.m33 - M.m23 * M.m13) + M.m13 * (M.m12 * M.m23 - M.m22 * M.m13);
  return {sqrt(r2 * c11 / det), sqrt(r2 * c22 / det), sqrt(r2 * c33 / det)};
}

}  // namespace anisocert::geometry
