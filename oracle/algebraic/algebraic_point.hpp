#pragma once
// A real point with algebraic coordinates, under one interface for the three kinds the oracle
// needs: rational points, points of one conic with a rational x (sample points), and common
// real roots of two conics (Voronoi vertices, LS Proposition 2). Internally
//   x = X_num(u)/X_den(u),  y = Y_num(u)/Y_den(u)
// for a real algebraic parameter u, with X_den(u), Y_den(u) ≠ 0; each coordinate also carries
// a defining polynomial so that coordinates of different points can be compared exactly.

#include "oracle/algebraic/bivariate.hpp"
#include "oracle/algebraic/real_algebraic.hpp"

#include <optional>
#include <string>

namespace anisocert::oracle {

class AlgebraicPoint {
 public:
  static AlgebraicPoint rational(const Rational& x, const Rational& y);
  // The points of conic C above x = x0: roots y of C(x0, y) (none, one or two; throws
  // std::invalid_argument if C(x0, y) vanishes identically).
  static std::vector<AlgebraicPoint> on_conic_at(const Conic& C, const Rational& x0);
  // Used by conic_intersection: u the parameter, the coordinate maps, and the defining
  // polynomials of x and y (non-zero, with x and y among their roots).
  AlgebraicPoint(RealAlgebraic u, Polynomial x_num, Polynomial x_den, Polynomial y_num, Polynomial y_den,
                 Polynomial x_defining, Polynomial y_defining);

  // sign(P(x, y)), exact, zero included.
  Sign sign_of(const Bivariate& P) const;
  // The coordinates as real algebraic numbers (isolated for their defining polynomials).
  const RealAlgebraic& x() const;
  const RealAlgebraic& y() const;
  // Correctly rounded to `digits` significant digits.
  std::string x_decimal(int digits) const { return x().decimal(digits); }
  std::string y_decimal(int digits) const { return y().decimal(digits); }

 private:
  RealAlgebraic coordinate(const Polynomial& defining, const Polynomial& num, const Polynomial& den) const;
  RealAlgebraic u_;
  Polynomial xn_, xd_, yn_, yd_, xdef_, ydef_;
  mutable std::optional<RealAlgebraic> x_, y_;
};

// Exact comparisons: sign(p.x − q.x), sign(p.y − q.y); points equal iff both coordinates are.
Sign compare_x(const AlgebraicPoint& p, const AlgebraicPoint& q);
Sign compare_y(const AlgebraicPoint& p, const AlgebraicPoint& q);
bool same_point(const AlgebraicPoint& p, const AlgebraicPoint& q);

}  // namespace anisocert::oracle
