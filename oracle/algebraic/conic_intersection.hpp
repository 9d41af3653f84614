#pragma once
// All real common roots of two conics, with multiplicities, exactly; or the report that they
// share a component (infinitely many common points). Voronoi vertices of the 2D anisotropic
// diagram are such points for pairs of bisector conics (LS Proposition 2).
//
// Method: a shear x = u − t·y with a small rational t chosen so that (i) both conics keep
// their degree in y with a constant leading coefficient, and (ii) every fibre u = u₀ above a
// root of the resultant R_t(u) = Res_y(A_t, B_t) meets the common zero set in exactly one point,
// checked exactly: where the first subresultant coefficient s₁ is non-zero the fibre's gcd is
// linear (y = −s₀/s₁); where s₁ vanishes, both restrictions must have a double root (their
// discriminants vanish on gcd(R_t, s₁)), so the fibre holds one point y = −α₁/(2α₂). Then the
// real roots u_i of R_t are in bijection with the real common points, the intersection
// multiplicity is the multiplicity of u_i as a root of R_t, and x = u − t·y.

#include "oracle/algebraic/algebraic_point.hpp"

#include <vector>

namespace anisocert::oracle {

struct IntersectionPoint {
  AlgebraicPoint point;
  int multiplicity;
};

struct ConicIntersection {
  bool shared_component = false;  // then `points` is empty
  std::vector<IntersectionPoint> points;  // sorted by x, then y
};

// Throws std::invalid_argument if a conic has all six coefficients zero (the whole plane).
ConicIntersection intersect(const Conic& A, const Conic& B);

// Res_y(A(u − t y, y), B(u − t y, y)) as a polynomial in u, for the actual y-degrees of the
// sheared conics: it vanishes at u = x + t y of every common point; it is the zero polynomial
// when the conics share a factor of positive degree in y (a factor in u alone, e.g. a common
// vertical line at t = 0, is not detected here; intersect() only uses t where both leading
// coefficients in y are non-zero constants, so that every common factor has positive y-degree).
Polynomial sheared_resultant(const Conic& A, const Conic& B, const Rational& t);

}  // namespace anisocert::oracle
