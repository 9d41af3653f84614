#pragma once
// x-monotone branches of a curve G(x, y) = 0 that is not vertical anywhere (the oracle's sheared
// coordinates, see diagram_input.hpp): a line e·y + (d·x + f) = 0 with e ≠ 0 (one branch), or a
// conic with c ≠ 0, whose points above x are the roots of c·y² + (b·x + e)·y + (a·x² + d·x + f).
// The upper branch (+1) is the larger root, the lower (−1) the smaller; they meet where the
// discriminant disc(x) = (b·x + e)² − 4c(a·x² + d·x + f) vanishes. With L = ∂G/∂y = 2c·y + b·x + e,
// a point of G is on the upper branch iff sign(c)·L ≥ 0 and on the lower iff sign(c)·L ≤ 0.
#include "oracle/algebraic/located_point.hpp"
#include "oracle/algebraic/polynomial.hpp"

namespace anisocert::oracle {

struct Branch {
  Conic curve;
  int side;  // +1 upper, −1 lower, 0 for a line

  // sign(p.y − y_branch(p.x)), exact; p.x must be in the branch's x-domain (disc(p.x) ≥ 0).
  Sign compare_point(const LocatedPoint& p) const;
  // The point of the branch above the rational x0 (in its x-domain, disc(x0) > 0 for conics):
  // filtered, from the quadratic formula in intervals when both roots come out apart (the
  // exact point is then built only if a decision needs it), else exact, its box refined below
  // `width`.
  LocatedPoint at(const Rational& x0, const Rational& width) const;
  // Whether a point of the curve lies on this branch.
  bool holds(const LocatedPoint& p) const;
  // Which side of the branch belongs to the region G > 0: +1 above, −1 below.
  int positive_side() const;
};

// disc(x) of a conic (zero polynomial for lines, whose x-domain is everything).
Polynomial discriminant_in_x(const Conic& G);
// ∂G/∂y.
Conic derivative_in_y(const Conic& G);
// The curve's kind, from its degree and the discriminant in x.
bool is_line(const Conic& G);

}  // namespace anisocert::oracle
