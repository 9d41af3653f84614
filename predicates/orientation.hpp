#pragma once
// Orientation of three points (LS Lemma 6; BWY §3.2.1, non-flat triangles).
// P = (bx − ax)(cy − ay) − (by − ay)(cx − ax): degree 2 in the coordinates.
// Positive when a, b, c turn counter-clockwise, zero when collinear.

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct OrientationKernel {
  static constexpr const char* name = "orientation";
  static constexpr std::size_t arity = 6;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0};
  static constexpr std::array<const char*, arity> inputs{"a.x", "a.y", "b.x", "b.y", "c.x", "c.y"};
  static constexpr std::array<int, arity> origin{0, 1, 0, 1, 0, 1};  // differences from a
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return (x[2] - x[0]) * (x[5] - x[1]) - (x[3] - x[1]) * (x[4] - x[0]);
  }
};

template <class S>
Sign orientation(const Point2<S>& a, const Point2<S>& b, const Point2<S>& c) {
  // Points on one axis-parallel line (boundary sites of a box) are collinear: exact, and it spares
  // the exact fall-back that the filter cannot avoid for a zero.
  if ((a.x == b.x && b.x == c.x) || (a.y == b.y && b.y == c.y)) {
    require_finite<S>("orientation", {{"a.x", a.x}, {"a.y", a.y}, {"b.x", b.x}, {"b.y", b.y}, {"c.x", c.x}, {"c.y", c.y}});
    return Sign::zero;
  }
  return filtered_sign<OrientationKernel>(std::array<S, 6>{a.x, a.y, b.x, b.y, c.x, c.y});
}

}  // namespace anisocert::predicates
