#pragma once
// Voronoi vertices for the refiners, certified (issue 16's "fast machinery", shared by the LS and
// BWY refiners): the points equidistant from three sites a, b, c (LS §7: where three cells can
// meet) are isolated in double boxes by Krawczyk's operator (krawczyk.hpp), and a sign at such a
// point is read from the box when it can be, else from the point enclosed at 128, 256, 512 and
// 1024 bits (MPFI), else exactly when the three metrics are equal (the point is rational). A
// sign none of these decides is reported undecided: the caller treats the configuration as
// degenerate, never guesses.
//
// This is the refiners' own machinery, apart from the oracle's exact algebraic points, which
// the refiners must not use (DESIGN.md § Layers): tests compare the two.

#include "numbers/filter_interval.hpp"
#include "numbers/interval.hpp"
#include "numbers/sign.hpp"
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
  int boxes = 0;                    // boxes examined
};

// Every point equidistant from the three sites in the closed box `search` (and perhaps some just
// beyond it), each certified, with `complete`; or complete = false when a part of the box could
// not be decided within `budget` boxes: a tangency (a double point), curves sharing a component,
// or sites that coincide.
VertexSearch vertices_in(const Trio& s, const Box2<FilterInterval>& search, int budget = 4000);

// Whether two vertex boxes of the same Trio hold the same point: true or false when certified,
// nothing when their boxes overlap without either isolating box holding the other's box.
std::optional<bool> same_vertex(const VertexBox& u, const VertexBox& v);

// The point enclosed at `bits` of precision (Krawczyk iterated in MPFI from the isolating box).
Box2<Interval> enclose(const Trio& s, const VertexBox& v, mpfr_prec_t bits);

// The point, exactly, when the three metrics are equal (then F is linear); nothing otherwise.
std::optional<Point2<Rational>> rational_vertex(const Trio& s);

// sign(f(x, y)) at the vertex. `f(x, y, of)` computes in the number type T of x and y, with
// of(d) the T that denotes the double d; it is called with FilterInterval, Interval and, for
// equal metrics, Rational. Nothing when undecided (a value that is zero, or too close to it).
template <class F>
std::optional<Sign> sign_at(const Trio& s, const VertexBox& v, F f) {
  if (auto sign = f(v.box.x, v.box.y, [](double d) { return FilterInterval(d); }).sign()) return sign;
  if (auto p = rational_vertex(s)) return sign_of(f(p->x, p->y, [](double d) { return Rational(d); }));
  for (mpfr_prec_t bits = 128; bits <= 1024; bits *= 2) {
    const Box2<Interval> X = enclose(s, v, bits);
    const Interval value = f(X.x, X.y, [bits](double d) { return Interval(d, bits); });
    if (value.certainly_positive()) return Sign::positive;
    if (value.certainly_negative()) return Sign::negative;
  }
  return std::nullopt;
}

}  // namespace anisocert::refiners::common
