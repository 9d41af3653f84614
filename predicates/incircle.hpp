#pragma once
// In-circle for a metric M (LU Definition 2.1; Del_M is the Delaunay triangulation of the
// points mapped by F, M = FᵀF): the lifted determinant with x ↦ xᵀMx,
//   P = det [ a−d  Q(a−d) ; b−d  Q(b−d) ; c−d  Q(c−d) ],  Q(x) = xᵀ M x,
// degree 4 in the coordinates, 1 in the metric. For counter-clockwise a, b, c: positive when d
// is strictly inside the M-circumellipse of abc, zero when the four are M-cocircular.
// (P(a, b, c, d) = det F⁻¹ · incircle(Fa, Fb, Fc, Fd), the Euclidean one.)

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct InCircleKernel {
  static constexpr const char* name = "in-circle";
  static constexpr std::size_t arity = 11;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"a.x", "a.y", "b.x", "b.y",   "c.x",  "c.y",
                                                         "d.x", "d.y", "M.m11", "M.m12", "M.m22"};
  static constexpr std::array<int, arity> origin{6, 7, 6, 7, 6, 7, 6, 7, -1, -1, -1};  // differences from d
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const T adx = x[0] - x[6], ady = x[1] - x[7], bdx = x[2] - x[6], bdy = x[3] - x[7], cdx = x[4] - x[6],
            cdy = x[5] - x[7];
    const T alift = quadratic_form(x[8], x[9], x[10], adx, ady);
    const T blift = quadratic_form(x[8], x[9], x[10], bdx, bdy);
    const T clift = quadratic_form(x[8], x[9], x[10], cdx, cdy);
    return alift * (bdx * cdy - bdy * cdx) + blift * (cdx * ady - cdy * adx) + clift * (adx * bdy - ady * bdx);
  }
};

template <class S>
Sign incircle(const Point2<S>& a, const Point2<S>& b, const Point2<S>& c, const Point2<S>& d, const Sym2<S>& M) {
  return filtered_sign<InCircleKernel>(
      std::array<S, 11>{a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y, M.m11, M.m12, M.m22});
}

}  // namespace anisocert::predicates
