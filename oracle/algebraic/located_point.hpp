#pragma once
// An exact algebraic point together with a double box around it, for filtered signs: the sign of
// a conic at the point is read from its interval value on the box when that excludes zero, and
// decided exactly otherwise (DESIGN.md: a filter may only speed up, never change, an answer).
#include "oracle/algebraic/algebraic_point.hpp"
#include "numbers/filter_interval.hpp"

namespace anisocert::oracle {

struct LocatedPoint {
  AlgebraicPoint point;
  anisocert::FilterInterval x, y;  // boxes containing the exact coordinates

  // Refines the coordinates' isolating intervals below `width` (a positive rational).
  LocatedPoint(AlgebraicPoint p, const Rational& width);
  static LocatedPoint rational(const Rational& x, const Rational& y);

  Sign sign_of(const Conic& G) const;
  // Interval value of G on the box (for callers that compare several values first).
  anisocert::FilterInterval value(const Conic& G) const;
  // Whether the boxes of two points are disjoint (then the points differ).
  bool apart_from(const LocatedPoint& q) const;
};

// Exact equality of points, with the box test first.
bool same_point(const LocatedPoint& p, const LocatedPoint& q);
// sign(p.x − q.x), sign(p.y − q.y), exact, boxes first.
Sign compare_x(const LocatedPoint& p, const LocatedPoint& q);
Sign compare_y(const LocatedPoint& p, const LocatedPoint& q);
// sign(p.x − x0), exact.
Sign compare_x(const LocatedPoint& p, const Rational& x0);

}  // namespace anisocert::oracle
