#pragma once
// Voronoi vertices for the refiners, certified (issue 16's "fast machinery", shared by the LS and
// BWY refiners): the points equidistant from three sites a, b, c (LS §7: where three cells can
// meet) are isolated in double boxes by Krawczyk's operator (krawczyk.hpp), enclosed at any
// precision on demand, and exact when the three metrics are equal (then the point is rational).
// Signs at them: certified_point.hpp.
//
// This is the refiners' own machinery, apart from the oracle's exact algebraic points, which
// the refiners must not use (DESIGN.md § Layers): tests compare the two.

#include "numbers/filter_interval.hpp"
#include "numbers/interval.hpp"
#include "refiners/common/krawczyk.hpp"

#include <optional>
#include <vector>

namespace anisocert::refiners::common {

using Trio = std::array<MetricSite, 3>;

// A point equidistant from the three sites of a Trio.
struct VertexBox {
  Box2<FilterInterval> box;        // contains the point
  Box2<FilterInterval> isolating;  // contains no other point equidistant from the three sites
  Point2<double> approx() const { return {box.x.midpoint().lo, box.y.midpoint().lo}; }
};

struct VertexSearch {
  std::vector<VertexBox> vertices;  // disjoint boxes, one point each
  bool complete = true;             // false: some point in the search box may be missing
  // The Jacobian of F vanishes everywhere (decided exactly): no point equidistant from the three
  // sites is a simple zero, so none can be certified. The search then only excludes the box
  // (complete, no vertex: F's centred form has no zero on it or on its halves, up to 256 boxes)
  // or leaves it undecided.
  bool singular = false;
  int boxes = 0;                    // boxes examined
};

// Every point equidistant from the three sites in the closed box `search` (and perhaps some
// beyond it: Newton's method may land up to a box's width outside the box it starts from), each
// certified, with `complete`; or complete = false when a part of the box could not be decided
// within `budget` boxes: a tangency (a double point), curves sharing a component, sites that
// coincide, or, rarely, a simple point so ill-conditioned that its boxes reach the resolution of
// doubles before Krawczyk can isolate it.
VertexSearch vertices_in(const Trio& s, const Box2<FilterInterval>& search, int budget = 4000);

// Whether two vertex boxes of the same Trio hold the same point: true or false when certified,
// nothing when their boxes overlap without either isolating box holding the other's box.
std::optional<bool> same_vertex(const VertexBox& u, const VertexBox& v);

// The point enclosed at `bits` of precision (Krawczyk iterated in MPFI from the double box).
Box2<Interval> enclose(const Trio& s, const VertexBox& v, mpfr_prec_t bits);

// The point, exactly, when the three metrics are equal (then F is linear); nothing otherwise.
std::optional<Point2<Rational>> rational_vertex(const Trio& s);

}  // namespace anisocert::refiners::common
