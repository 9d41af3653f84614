// The edge level (refiners/common/boundary.hpp): which subsegment a point picked outside Ω splits
// instead of being inserted (Insert_or_snap), and where a subsegment is split.
#include "fields/registry.hpp"
#include "refiners/common/boundary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

namespace {

using namespace anisocert;
using predicates::Point2;

// x = (2, −0.9) lies outside the unit square, encroaches no edge, and the segment to it from
// g = (3, −0.9) (both outside) crosses none, so the fall-back applies: the subsegment whose
// diametral ellipse in M is nearest to x, measured as (x − m)ᵀM(x − m) − ‖b − a‖²_M / 4 for its
// midpoint m. Under M = I that is 1 + 1.96 − 0.25 = 2.71 for the right edge and
// 2.25 + 0.81 − 0.25 = 2.81 for the bottom edge: the right edge, (1, 0)–(1, 1).
TEST(Boundary, OutsidePointCrossingNoSubsegmentSplitsTheNearest) {
  const auto isotropic = fields::make_field("constant", {{"m11", 1}, {"m12", 0}, {"m22", 1}});
  const refiners::common::Domain domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  refiners::common::Sites sites(domain, isotropic);
  for (const Point2<double>& q : domain.corners()) sites.add(q);
  const refiners::common::Boundary boundary(domain, sites);
  const predicates::Sym2<double> I{1, 0, 1};
  const std::optional<int> s = boundary.snap({2, -0.9}, I, I, {3, -0.9});
  ASSERT_TRUE(s);
  const auto [a, b] = boundary.segments()[*s];
  EXPECT_EQ(sites.points[a].x, 1);
  EXPECT_EQ(sites.points[a].y, 0);
  EXPECT_EQ(sites.points[b].x, 1);
  EXPECT_EQ(sites.points[b].y, 1);
}

// The rectangle with corners (±1, ±0.4) (0.4 as a double, an odd multiple of 2⁻⁵⁴; the regression
// domain-without-double-midpoints): edge 0 from (1, −0.4) to (1, 0.4) halved 40 times towards its
// first end. Each split point lies exactly on the edge (x = 1), strictly between the subsegment's
// ends, and is a double nearest the rational midpoint, checked here against its two neighbouring
// doubles in rationals; where that midpoint is a double (0, −0.2) it is the midpoint itself.
TEST(Boundary, AxisParallelSubsegmentsSplitAtTheDoubleNearestTheirMidpoint) {
  const auto isotropic = fields::make_field("constant", {{"m11", 1}, {"m12", 0}, {"m22", 1}});
  const double f = 0.4;
  const refiners::common::Domain domain({{1, -f}, {1, f}, {-1, f}, {-1, -f}});
  refiners::common::Sites sites(domain, isotropic);
  for (const Point2<double>& q : domain.corners()) sites.add(q);
  refiners::common::Boundary boundary(domain, sites);
  int exact_midpoints = 0;
  for (int k = 0; k < 40; ++k) {
    const auto [a, b] = boundary.segments()[0];
    const Rational ya(sites.points[static_cast<std::size_t>(a)].y), yb(sites.points[static_cast<std::size_t>(b)].y);
    const Rational mid = (ya + yb) / 2;
    const auto split = boundary.begin_split(0);
    ASSERT_TRUE(std::holds_alternative<Point2<double>>(split)) << k << ": " << std::get<std::string>(split);
    const Point2<double> p = std::get<Point2<double>>(split);
    EXPECT_EQ(p.x, 1) << k;
    const Rational y(p.y);
    EXPECT_TRUE(std::min(ya, yb) < y && y < std::max(ya, yb)) << k;
    for (const double other : {std::nextafter(p.y, -INFINITY), std::nextafter(p.y, INFINITY)})
      EXPECT_LE(abs(y - mid), abs(Rational(other) - mid)) << k;
    exact_midpoints += y == mid;
    sites.add(p);
    boundary.site_added();
    boundary.end_split(0);
  }
  EXPECT_GE(exact_midpoints, 2);  // 0 and −0.2
  EXPECT_LT(exact_midpoints, 40);  // −0.3 is no double
}

}  // namespace
