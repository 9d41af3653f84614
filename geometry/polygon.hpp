#pragma once
// Polygons: the domain Ω (LS §5, LU §4: a simple polygon, its corners counter-clockwise) and the
// tests every layer asks of it, written once over the scalar type S (Rational, or double taken as
// the rational it denotes). Every decision is an exact orientation (predicates/orientation.hpp):
// no tolerance, for doubles as for rationals.
#include "predicates/orientation.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace anisocert::geometry {

using predicates::Point2;

template <class S>
using Polygon = std::vector<Point2<S>>;

// p on the closed segment [a, b].
template <class S>
bool on_segment(const Point2<S>& p, const Point2<S>& a, const Point2<S>& b) {
  return predicates::orientation(a, b, p) == Sign::zero && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// How two closed segments [p1, p2] and [q1, q2] meet: not at all; crossing (each has its
// endpoints strictly on both sides of the other's line, so their interiors cross at one point);
// or touching (an endpoint of one lies on the other, collinear overlaps included).
enum class Meeting { none, crossing, touching };

// The crossing case alone (four orientations): what visibility across ∂Ω asks. Segments whose
// bounding boxes are disjoint cannot cross (the crossing point lies in both boxes): decided by
// comparisons first, which only spares orientations (a Ω of a mesh's hundreds of boundary
// vertices, `refine --from`, asks this of every edge).
template <class S>
bool segments_cross(const Point2<S>& p1, const Point2<S>& p2, const Point2<S>& q1, const Point2<S>& q2) {
  using predicates::orientation;
  if (std::max(p1.x, p2.x) < std::min(q1.x, q2.x) || std::max(q1.x, q2.x) < std::min(p1.x, p2.x) ||
      std::max(p1.y, p2.y) < std::min(q1.y, q2.y) || std::max(q1.y, q2.y) < std::min(p1.y, p2.y))
    return false;
  return orientation(p1, p2, q1) * orientation(p1, p2, q2) == Sign::negative &&
         orientation(q1, q2, p1) * orientation(q1, q2, p2) == Sign::negative;
}

template <class S>
Meeting segments_meet(const Point2<S>& p1, const Point2<S>& p2, const Point2<S>& q1, const Point2<S>& q2) {
  if (segments_cross(p1, p2, q1, q2)) return Meeting::crossing;
  if (on_segment(q1, p1, p2) || on_segment(q2, p1, p2) || on_segment(p1, q1, q2) || on_segment(p2, q1, q2))
    return Meeting::touching;
  return Meeting::none;
}

// p in the closed polygon: on an edge, or inside by the crossing number of the ray from p towards
// +x (an edge counts when one endpoint is strictly above p and the other is not; p off the edge
// is then strictly left or right of it, and the crossing is to the right of p when p is left of
// an upward edge or right of a downward one). An edge whose height range misses p's can neither
// hold p nor count, so it costs no orientation; the others cost one.
template <class S>
bool in_closed_polygon(const Point2<S>& p, const Polygon<S>& polygon) {
  const std::size_t m = polygon.size();
  bool inside = false;
  for (std::size_t k = 0; k < m; ++k) {
    const Point2<S>& a = polygon[k];
    const Point2<S>& b = polygon[(k + 1) % m];
    if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) continue;
    const Sign o = predicates::orientation(a, b, p);
    if (o == Sign::zero && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x)) return true;
    if ((a.y > p.y) != (b.y > p.y) && (o == Sign::positive) == (a.y < b.y)) inside = !inside;
  }
  return inside;
}

// No corner turns right: a convex polygon (for a simple counter-clockwise one).
template <class S>
bool is_convex(const Polygon<S>& polygon) {
  const std::size_t m = polygon.size();
  for (std::size_t k = 0; k < m; ++k)
    if (predicates::orientation(polygon[k], polygon[(k + 1) % m], polygon[(k + 2) % m]) == Sign::negative) return false;
  return true;
}

// The first reason a polygon is not simple and counter-clockwise, with the corners or edges it
// concerns (edge k runs from corner k to corner k + 1 mod m), checked in this order: an edge of
// length zero; adjacent edges overlapping (the boundary folds back at a corner; a straight run
// through a corner is allowed); non-adjacent edges meeting (crossing, or touching at `at`); a
// negative signed area. Nothing when the polygon is simple and counter-clockwise.
struct PolygonDefect {
  enum class Kind { zero_length_edge, folds_back, edges_meet, clockwise } kind;
  std::size_t i = 0, j = 0;      // zero_length_edge: the edge i; folds_back: the corner i; edges_meet: edges i < j
  bool crossing = false;         // edges_meet: a proper crossing (else they touch)
  Point2<Rational> at{};         // edges_meet: where
};
std::optional<PolygonDefect> simplicity_defect(const Polygon<Rational>& polygon);

// Ω with every point of `points` that lies on an edge inserted as a corner, in order along the
// edge: the polygon whose edges are the subsegments between consecutive points of ∂Ω (LS
// Theorem 7 reads Ω's vertices and edges so: the sites on ∂Ω split its edges). Same set, same
// orientation; `point` gives for each corner the index of the point at it (−1 when none is).
// Points are taken once each; a point at a corner names that corner.
struct SplitPolygon {
  Polygon<Rational> corners;
  std::vector<int> point;
};
SplitPolygon split_at_points(const Polygon<Rational>& polygon, const std::vector<Point2<Rational>>& points);

// "(x, y)" as messages name a point: each coordinate as exact_excerpt shows it (numbers/excerpt.hpp:
// its exact text when short, else about ten digits), so that a message stays one short line.
std::string point_excerpt(const Point2<Rational>& p);

// One line on the defect, naming corners as name[k] (e.g. "domain[3]") and points as point_excerpt does.
std::string describe(const PolygonDefect& defect, const Polygon<Rational>& polygon, const std::string& name);

}  // namespace anisocert::geometry
