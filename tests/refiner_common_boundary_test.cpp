// The edge level's Insert_or_snap (refiners/common/boundary.hpp): which subsegment a point picked
// outside Ω splits instead of being inserted.
#include "fields/registry.hpp"
#include "refiners/common/boundary.hpp"

#include <gtest/gtest.h>

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

}  // namespace
