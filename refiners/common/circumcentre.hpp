#pragma once
// The M-circumcentre p of three sites a, b, c (not collinear), the Voronoi vertex of sites that
// share one metric M (LS §3: d_v(p) = |F(p − v)| with M = FᵀF, so the vertex is equidistant in
// M): 2 (b − a)ᵀM (p − a) = |b − a|²_M and likewise for c, solved by Cramer's rule,
//   p = a + (nx, ny) / det,
// nx, ny and det polynomials in u = b − a, w = c − a and M (degree 3 and 2 in u, w; 2 in M).
// One template for every number type, as the predicates' kernels: exactly (Rational, Expansion),
// a box (FilterInterval), or doubles with a static error bound (circumcentre_box).
#include "numbers/expansion.hpp"
#include "numbers/filter_interval.hpp"
#include "numbers/rational.hpp"
#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

#include <array>

namespace anisocert::refiners::common {

using predicates::Point2;
using predicates::Sym2;

template <class T>
struct CircumcentreParts {
  T nx, ny, det;
};
template <class T>
constexpr CircumcentreParts<T> circumcentre_parts(const T& ux, const T& uy, const T& wx, const T& wy, const T& m11, const T& m12,
                                                  const T& m22) {
  // Rows M u and M w; right-hand sides |u|²_M / 2 and |w|²_M / 2.
  const T r11 = m11 * ux + m12 * uy, r12 = m12 * ux + m22 * uy, r21 = m11 * wx + m12 * wy, r22 = m12 * wx + m22 * wy;
  const T U = (r11 * ux + r12 * uy) * T(0.5), W = (r21 * wx + r22 * wy) * T(0.5);
  return {U * r22 - W * r12, r11 * W - r21 * U, r11 * r22 - r12 * r21};
}
template <class T>
CircumcentreParts<T> circumcentre_parts(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const T ax(a.x), ay(a.y);
  return circumcentre_parts<T>(T(b.x) - ax, T(b.y) - ay, T(c.x) - ax, T(c.y) - ay, T(M.m11), T(M.m12), T(M.m22));
}

// The circumcentre in T: exactly (Rational), or a box holding it (FilterInterval; unbounded when
// the box of det holds 0).
template <class T>
Point2<T> circumcentre_in(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const CircumcentreParts<T> p = circumcentre_parts<T>(a, b, c, M);
  return {T(a.x) + p.nx / p.det, T(a.y) + p.ny / p.det};
}

// nx, ny or det as a kernel of predicates/filtered_sign.hpp, measured from a (Translatable), so
// that its static error bound is derived at compile time from the polynomial itself.
template <int part>
struct CircumcentrePartKernel {
  static constexpr const char* name = "circumcentre";
  static constexpr std::size_t arity = 9;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"a.x", "a.y", "b.x", "b.y", "c.x", "c.y", "M.m11", "M.m12", "M.m22"};
  static constexpr std::array<int, arity> origin{0, 1, 0, 1, 0, 1, -1, -1, -1};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const CircumcentreParts<T> p = circumcentre_parts<T>(x[2] - x[0], x[3] - x[1], x[4] - x[0], x[5] - x[1], x[6], x[7], x[8]);
    if constexpr (part == 0) {
      return p.nx;
    } else if constexpr (part == 1) {
      return p.ny;
    } else {
      return p.det;
    }
  }
};

// A box holding the circumcentre: nx, ny and det in doubles on the rounded differences, each
// within its static bound (predicates::translated_error_model), when the differences and M are
// in the static range and det's box is clear of 0; in FilterInterval otherwise.
Point2<FilterInterval> circumcentre_box(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M);

// The circumcentre rounded to the nearest doubles (Boost's conversion of the rational
// circumcentre): by one division when its parts are exact in doubles (numbers/exact_double.hpp),
// else from its parts in expansions (numbers/expansion.hpp), and in rationals only when those
// cannot decide.
Point2<double> rounded_circumcentre(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M);

// The circumcentre exactly: from one division per coordinate when its parts are exact in doubles
// and the quotients too (a grid's right triangles, whose vertices lie on the grid or halfway),
// circumcentre_in<Rational> otherwise.
Point2<Rational> exact_circumcentre(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M);

}  // namespace anisocert::refiners::common
