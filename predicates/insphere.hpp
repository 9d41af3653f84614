#pragma once
// In-sphere for a metric M (LU §3: the circumsphere of a tetrahedron in the metric M_v of its
// vertex v, whose emptiness makes the star of v Delaunay in M_v): the lifted determinant with
// x ↦ xᵀMx, negated,
//   P = −det [ a−e  Q(a−e) ; b−e  Q(b−e) ; c−e  Q(c−e) ; d−e  Q(d−e) ],  Q(x) = xᵀ M x,
// degree 5 in the coordinates, 1 in the metric. For positively oriented a, b, c, d
// (orientation3.hpp): positive when e is strictly inside the M-circumellipsoid of abcd, zero when
// the five are M-cospherical. (With M = FᵀF, P = det F⁻¹ · insphere(Fa, …, Fe), Euclidean; for the
// unit tetrahedron and e = (1/4, 1/4, 1/4), inside, the determinant is −9/16.)

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct InSphereKernel {
  static constexpr const char* name = "in-sphere";
  static constexpr std::size_t arity = 21;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"a.x",   "a.y",   "a.z",   "b.x",   "b.y",   "b.z",  "c.x",
                                                         "c.y",   "c.z",   "d.x",   "d.y",   "d.z",   "e.x",  "e.y",
                                                         "e.z",   "M.m11", "M.m12", "M.m13", "M.m22", "M.m23", "M.m33"};
  static constexpr std::array<int, arity> origin{12, 13, 14, 12, 13, 14, 12, 13, 14, 12, 13, 14, 12, 13, 14, -1, -1, -1, -1, -1, -1};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const T ax = x[0] - x[12], ay = x[1] - x[13], az = x[2] - x[14];
    const T bx = x[3] - x[12], by = x[4] - x[13], bz = x[5] - x[14];
    const T cx = x[6] - x[12], cy = x[7] - x[13], cz = x[8] - x[14];
    const T dx = x[9] - x[12], dy = x[10] - x[13], dz = x[11] - x[14];
    const auto lift = [&](const T& u, const T& v, const T& w) { return quadratic_form(x[15], x[16], x[17], x[18], x[19], x[20], u, v, w); };
    // 2×2 minors of the (x, y) columns, shared by the four 3×3 minors.
    const T ab = ax * by - ay * bx, ac = ax * cy - ay * cx, ad = ax * dy - ay * dx;
    const T bc = bx * cy - by * cx, bd = bx * dy - by * dx, cd = cx * dy - cy * dx;
    const T bcd = bz * cd - cz * bd + dz * bc, acd = az * cd - cz * ad + dz * ac;
    const T abd = az * bd - bz * ad + dz * ab, abc = az * bc - bz * ac + cz * ab;
    // −det by the fourth column's cofactors (signs −, +, −, + down the column).
    return (lift(ax, ay, az) * bcd - lift(bx, by, bz) * acd) + (lift(cx, cy, cz) * abd - lift(dx, dy, dz) * abc);
  }
};

template <class S>
Sign insphere(const Point3<S>& a, const Point3<S>& b, const Point3<S>& c, const Point3<S>& d, const Point3<S>& e, const Sym3<S>& M) {
  return filtered_sign<InSphereKernel>(std::array<S, 21>{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z,
                                                        M.m11, M.m12, M.m13, M.m22, M.m23, M.m33});
}

}  // namespace anisocert::predicates
