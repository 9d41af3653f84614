#pragma once
// The input of the exact diagram (LS §3: sites v with metrics M_v; LS §5: a polygonal domain Ω)
// and the polynomials the oracle builds from it: the squared distance
//   Q_v(p) = (p − v)ᵀ M_v (p − v)          (LS §2, d_v(p)²)
// and the bisector conic F_vw = Q_v − Q_w (LS Proposition 2), with F_vw < 0 where v is closer.
//
// The oracle works in sheared coordinates x' = x + s·y, y' = y with a rational s chosen so that
// no bisector has a vertical asymptotic direction and no domain edge is vertical; then every
// curve is a graph y(x) on at most two branches, and x-monotone pieces, slabs and vertical rays
// need no special cases. Distances are preserved: v' = S v and M'_v = S⁻ᵀ M_v S⁻¹ with
// S = [1 s; 0 1], det S = 1, so orientations and wedge signs are preserved too.
#include "oracle/algebraic/bivariate.hpp"
#include "predicates/metric.hpp"
#include "geometry/mesh.hpp"
#include "predicates/point.hpp"
#include <vector>

namespace anisocert::oracle {

using predicates::Point2;
using predicates::Sym2;

// The diagram's input is the one mesh shape, of which it reads the sites, their metrics (positive
// definite, checked by whoever built it) and the domain (simple, counter-clockwise, likewise).
using geometry::Mesh;

Conic distance_conic(const Point2<Rational>& v, const Sym2<Rational>& M);
// F_vw = Q_v − Q_w: negative where v is strictly closer, positive where w is.
Conic bisector_conic(const Mesh<Rational>& in, int v, int w);
// LS Definition 2: the two linear forms whose positivity defines wedge(v, w):
//   toward_w(q) = (q − v)ᵀ M_v (w − v),  toward_v(q) = (q − w)ᵀ M_w (v − w).
Conic wedge_form(const Mesh<Rational>& in, int from, int to);

// G(x + s·y, y): the conic in original coordinates of a conic G given in coordinates sheared by
// s (and, with −s, the converse).
Conic shear_conic(const Conic& G, const Rational& s);
Mesh<Rational> shear_input(const Mesh<Rational>& in, const Rational& s);
// The smallest s in 0, 1/7, 2/7, … (alternating signs) for which no bisector of `pairs` has a
// vertical asymptotic direction (the y² coefficient of the sheared conic is non-zero or the
// conic is a non-vertical line) and no domain edge is vertical.
Rational choose_shear(const Mesh<Rational>& in, const std::vector<std::pair<int, int>>& pairs);

}  // namespace anisocert::oracle
