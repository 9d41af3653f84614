#pragma once
// The background field in doubles without rational arithmetic, when intervals allow it. In a
// triangle abc the P1 interpolation is affine (background.hpp), so
//   M(p) = M_a + (x − x_a) ∂M/∂x + (y − y_a) ∂M/∂y,
//   ∂M/∂x = ((M_b − M_a)(c_y − a_y) − (M_c − M_a)(b_y − a_y)) / [a b c],
//   ∂M/∂y = ((M_c − M_a)(b_x − a_x) − (M_b − M_a)(c_x − a_x)) / [a b c]
// (it gives M_a, M_b, M_c at the vertices). Evaluated in FilterInterval from enclosures of the
// vertices and their metrics, it encloses the exact M(p); and a rounding error of a vertex only
// counts times the gradient (the barycentric form divides it by the area instead). When the
// enclosure is not tight enough, the caller computes exactly.
#include "numbers/filter_interval.hpp"
#include "predicates/point.hpp"

#include <optional>

namespace anisocert::fields {

using predicates::Point2;
using predicates::Sym2;

struct P1Gradient {
  Sym2<FilterInterval> dx, dy;  // ∂M/∂x and ∂M/∂y, per component
};

P1Gradient p1_gradient(const Point2<FilterInterval>& a, const Point2<FilterInterval>& b, const Point2<FilterInterval>& c,
                       const Sym2<FilterInterval>& Ma, const Sym2<FilterInterval>& Mb, const Sym2<FilterInterval>& Mc);

// M(p) from the vertex a, its metric and the gradient.
Sym2<FilterInterval> p1_value(const Point2<FilterInterval>& a, const Sym2<FilterInterval>& Ma, const P1Gradient& g,
                              const Point2<FilterInterval>& p);

// The midpoints of an enclosure of M that pins each component down to 2⁻⁴¹ relative (m11 and m22
// of themselves, m12 of √(m11 m22), as positive definiteness bounds |m12|): widths at most 2⁻⁴⁰
// of those. Nothing otherwise (an enclosure touching a non-positive m11 or m22 included).
// FilterInterval widens every operation by an ulp, so a few dozen ulps is the most one can ask.
std::optional<Sym2<double>> tight_midpoints(const Sym2<FilterInterval>& M);

}  // namespace anisocert::fields
