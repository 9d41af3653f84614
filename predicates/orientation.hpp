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

// The sign of the difference u − w of two numbers, from a comparison (no subtraction, so it is
// exact for every finite double, subnormals and signed zeros included).
template <class S>
Sign sign_of_difference(const S& u, const S& w) {
  return u > w ? Sign::positive : u < w ? Sign::negative : Sign::zero;
}

template <class S>
Sign orientation(const Point2<S>& a, const Point2<S>& b, const Point2<S>& c) {
  // An axis-parallel ab (an edge of a box-shaped domain, or points on one such line): one product
  // of P vanishes exactly, P = −(b.y − a.y)(c.x − a.x) when a.x = b.x and (b.x − a.x)(c.y − a.y) when
  // a.y = b.y, so the sign is a product of the signs of two differences, each read off a
  // comparison: exact, and it spares
  // the exact fall-back that the filter cannot avoid for a zero.
  if (a.x == b.x || a.y == b.y) {
    if constexpr (std::is_same_v<S, double>)
      if (!(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(c.x) &&
            std::isfinite(c.y)))
        require_finite<S>("orientation", {{"a.x", a.x}, {"a.y", a.y}, {"b.x", b.x}, {"b.y", b.y}, {"c.x", c.x}, {"c.y", c.y}});
    if (a.x == b.x) return -(sign_of_difference(b.y, a.y) * sign_of_difference(c.x, a.x));
    return sign_of_difference(b.x, a.x) * sign_of_difference(c.y, a.y);
  }
  return filtered_sign<OrientationKernel>(std::array<S, 6>{a.x, a.y, b.x, b.y, c.x, c.y});
}

}  // namespace anisocert::predicates
