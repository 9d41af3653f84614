#pragma once
// An algebraic point known by a double box around it, for filtered decisions: the sign of a conic
// at the point is read from its interval value on the box when that excludes zero, two points
// whose boxes are apart are ordered by their boxes, and only otherwise is the exact point used
// (DESIGN.md: a filter may only speed up, never change, an answer). The exact point is either
// given at construction (exact constructions) or built from a recipe the first time a decision
// needs it (filtered constructions, issue 14): most points never need it.
//
// A LocatedPoint is a value: copies are independent, and one object is used by one thread at a
// time (building the exact point, or refining it, changes the object).
#include "oracle/algebraic/algebraic_point.hpp"
#include "oracle/algebraic/filter_context.hpp"
#include "numbers/filter_interval.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace anisocert::oracle {

// A box [x] × [y] of doubles.
struct IntervalBox {
  anisocert::FilterInterval x, y;
};

struct LocatedPoint {
  using Recipe = std::function<AlgebraicPoint()>;
  using Curves = std::function<std::pair<Conic, Conic>()>;

  anisocert::FilterInterval x, y;  // boxes containing the exact coordinates

  // An exact point, its coordinates' isolating intervals refined below `width` (a positive
  // rational) for the box.
  LocatedPoint(AlgebraicPoint p, const Rational& width);
  // A point known by a box that contains it; `recipe` builds it exactly, on first use. With
  // `curves`, the point is the one common point of the two curves in the box, which narrowed()
  // may enclose more tightly.
  LocatedPoint(const IntervalBox& box, std::shared_ptr<const Recipe> recipe, std::shared_ptr<const Curves> curves = nullptr);
  static LocatedPoint rational(const Rational& x, const Rational& y);

  // Copies are deep (the exact point, when built, is copied), so that two threads never share
  // one; a point not yet built exactly costs a pointer and its box.
  LocatedPoint(const LocatedPoint& o);
  LocatedPoint& operator=(const LocatedPoint& o);
  LocatedPoint(LocatedPoint&&) noexcept = default;
  LocatedPoint& operator=(LocatedPoint&&) noexcept = default;
  ~LocatedPoint();

  // The exact point.
  const AlgebraicPoint& exact() const;
  // A box of a few ulps around the point, proved by Krawczyk's operator in MPFI on its two curves
  // (narrowed_box.hpp), for decisions the box cannot take before the exact point is built;
  // nothing for a point given exactly or by no curves, or when not proved.
  std::optional<IntervalBox> narrowed() const;

  Sign sign_of(const Conic& G) const;
  // Interval value of G on the box (for callers that compare several values first).
  anisocert::FilterInterval value(const Conic& G) const;
  // Whether the boxes of two points are disjoint (then the points differ).
  bool apart_from(const LocatedPoint& q) const;
  // Whether q is a copy of this point, i.e. has the same construction (then they are equal).
  bool copy_of(const LocatedPoint& q) const { return recipe_ && recipe_ == q.recipe_; }

 private:
  std::shared_ptr<const Recipe> recipe_;
  std::shared_ptr<const Curves> curves_;
  mutable std::unique_ptr<AlgebraicPoint> exact_;
};

// Exact equality of points, with the box test first.
bool same_point(const LocatedPoint& p, const LocatedPoint& q);
// sign(p.x − q.x), sign(p.y − q.y), exact, boxes first.
Sign compare_x(const LocatedPoint& p, const LocatedPoint& q);
Sign compare_y(const LocatedPoint& p, const LocatedPoint& q);
// sign(p.x − x0), exact.
Sign compare_x(const LocatedPoint& p, const Rational& x0);

// The simplest rational strictly between the x-coordinates a.x < b.x: the dyadic k/2^m of least
// m (0 when a.x < 0 < b.x). It depends only on the two exact values, not on how they were
// computed, so the filtered and the exact constructions choose the same sample points.
Rational rational_between(const LocatedPoint& a, const LocatedPoint& b);
// The same between a.x and a rational x0 > a.x, or x0 < a.x.
Rational rational_between(const LocatedPoint& a, const Rational& x0);
Rational rational_between(const Rational& x0, const LocatedPoint& b);

}  // namespace anisocert::oracle
