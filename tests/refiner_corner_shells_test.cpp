// refiners/common/corner_shells: which vertices of X are apexes of small angles, where shells lie,
// and which triangles the shape rules leave, on hand-made configurations whose answers follow
// from the definitions (the 3-4-5 triangle's edge (0.75, 0.5625) is 0.9375 long and makes 36.87°
// with the x-axis; every point below is an exact double).
#include "refiners/common/corner_shells.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace anisocert;
using predicates::Point2;
using predicates::Sym2;
using refiners::common::CornerShells;
using refiners::common::Domain;

const Sym2<double> I{1, 0, 1};

// Corner 0 of the triangle (0, 0), (1, 0), (0.75, 0.5625) is 36.87°; its others are 66.04° and 77.09°.
const Domain triangle({{0, 0}, {1, 0}, {0.75, 0.5625}});

TEST(CornerShells, ApexesAreTheVerticesWithTwoSegmentsBelowSixtyDegreesInTheirMetric) {
  const CornerShells shells(triangle, std::vector(3, I));
  EXPECT_TRUE(shells.sharp(0));
  EXPECT_FALSE(shells.sharp(1));
  EXPECT_FALSE(shells.sharp(2));
  // In diag(1, 16) corner 0's edges (1, 0) and (0.75, 0.5625) meet at arctan(4 · 0.75) = 71.6°.
  EXPECT_FALSE(CornerShells(triangle, std::vector(3, Sym2<double>{1, 0, 16})).sharp(0));
  // The unit square has none; an interior segment from corner 0 to (0.75, 0.5625) makes one there
  // (36.87° to edge 0, 53.13° to edge 3), and none at its other end.
  const Domain square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0.75, 0.5625}}, {{0, 4}});
  const CornerShells in_square(square, std::vector(5, I));
  EXPECT_TRUE(in_square.sharp(0));
  for (int k = 1; k < 5; ++k) EXPECT_FALSE(in_square.sharp(k)) << k;
}

TEST(CornerShells, ShellsArePowersOfTwoFromTheApex) {
  const Domain square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0.75, 0.5625}}, {{0, 4}});
  const CornerShells shells(square, std::vector(5, I));
  const std::vector<Point2<double>> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.75, 0.5625}, {0.46875, 0}};
  // Subsegment from apex 0 to (0.46875, 0): the power of two in [L/3, 2L/3] is 1/4.
  ASSERT_TRUE(shells.parameter(0, 5, points));
  EXPECT_DOUBLE_EQ(*shells.parameter(0, 5, points), 0.25 / 0.46875);
  EXPECT_DOUBLE_EQ(*shells.parameter(5, 0, points), 1 - 0.25 / 0.46875);
  EXPECT_FALSE(shells.parameter(1, 5, points));  // no end at an apex: the refiner's midpoint
  // The lopping: every segment at apex 0 at 2^⌊log2(0.9375 / 2)⌋ = 1/4 from it.
  const auto first = shells.first();
  ASSERT_EQ(first.size(), 3u);
  for (const auto& s : first) {
    EXPECT_EQ(s.c, 0);
    const double length = s.o == 4 ? 0.9375 : 1;
    EXPECT_DOUBLE_EQ(s.t, 0.25 / length) << "to " << s.o;
  }
}

TEST(CornerShells, TheExemptTrianglesHaveTheirShortestEdgeAcrossTheAngleOnOneShell) {
  const CornerShells shells(triangle, std::vector(3, I));
  // Sites 3 and 4 at 0.46875 from corner 0, on edge 0 and on edge 2 (half of it).
  std::vector<Point2<double>> points{{0, 0}, {1, 0}, {0.75, 0.5625}, {0.46875, 0}, {0.375, 0.28125}, {0.875, 0.125}, {0.5, 0.0625},
                                     {0.1875, 0.140625}};
  EXPECT_TRUE(shells.exempt({3, 4, 5}, points));   // 3–4 (0.297) the shortest: across the angle
  EXPECT_TRUE(shells.exempt({5, 4, 3}, points));   // in any order
  EXPECT_FALSE(shells.exempt({3, 4, 6}, points));  // 3–6 (0.070) is shorter: not because of the angle
  EXPECT_FALSE(shells.exempt({3, 7, 5}, points));  // 7 at 0.234375: another shell
  EXPECT_FALSE(shells.exempt({1, 4, 5}, points));  // a corner is no split site
  EXPECT_TRUE(shells.exempt({0, 3, 4}, points));   // the triangle at the apex itself: 3–4 is its shortest edge
  // At the square's corner (90°) the same kind of triangle is no exemption; across an interior
  // segment at 36.87° to an edge it is.
  const std::vector<Point2<double>> in_square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.75, 0.5625}, {0.46875, 0}, {0.375, 0.28125}, {0.875, 0.125},
                                              {0, 0.46875}, {0.125, 0.875}};
  const Domain plain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), with_segment({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0.75, 0.5625}}, {{0, 4}});
  EXPECT_FALSE(CornerShells(plain, std::vector(4, I)).exempt({5, 8, 7}, in_square));
  EXPECT_TRUE(CornerShells(with_segment, std::vector(5, I)).exempt({5, 6, 7}, in_square));
}

}  // namespace
