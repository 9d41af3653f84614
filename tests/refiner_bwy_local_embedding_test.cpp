// BWY §3.2.1's local embedding and rule 5's overlap test on hand-built sets T. The expected verdicts
// come from the triangulations drawn here: six sites (the unit square's corners 0–3, interior sites 4
// and 5), six counter-clockwise triangles whose orientations are worked out in the comments.
#include "refiners/bwy/local_embedding.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using anisocert::predicates::Point2;
using anisocert::refiners::bwy::Constraint;
using anisocert::refiners::bwy::DualTriangles;
using anisocert::refiners::bwy::embedding_failure;
using anisocert::refiners::bwy::overlaps;

std::vector<Point2<double>> six_sites(Point2<double> site4 = {0.3, 0.4}) { return {{0, 0}, {1, 0}, {1, 1}, {0, 1}, site4, {0.6, 0.55}}; }
const std::vector<Constraint> square_sides{{0, 1, true}, {1, 2, true}, {2, 3, true}, {3, 0, true}};

// A triangulation of the square with interior sites 4 = (0.3, 0.4) and 5 = (0.6, 0.55): 2·6 − 4 − 2 = 6
// triangles, each counter-clockwise (e.g. 0,5,4: (0.6,0.55)×(0.3,0.4) = 0.075 > 0), every interior
// edge in two and every side in one.
DualTriangles six_triangles(bool without_0_5_4 = false) {
  DualTriangles T;
  const std::vector<std::array<int, 3>> ts{{0, 1, 5}, {0, 5, 4}, {0, 4, 3}, {4, 5, 3}, {5, 2, 3}, {1, 2, 5}};
  for (std::size_t k = 0; k < ts.size(); ++k)
    if (!(without_0_5_4 && k == 1)) T.add(static_cast<int>(k), ts[k], false);
  return T;
}

TEST(BWY_LocalEmbedding, ATriangulationOfTheSquareIsOne) {
  const DualTriangles T = six_triangles();
  EXPECT_EQ(embedding_failure(T, six_sites(), square_sides), "");
  for (int t : T.alive()) EXPECT_FALSE(overlaps(T, t, six_sites())) << t;
}

TEST(BWY_LocalEmbedding, AHoleWhoseEdgesAreNoSubsegmentIsFound) {
  // Without triangle 0,5,4 every site is still a vertex and every side in one triangle; edge 5–0 (of
  // the first triangle) is in one triangle only.
  EXPECT_EQ(embedding_failure(six_triangles(true), six_sites(), square_sides), "the edge 5–0 is in 1 triangles");
}

TEST(BWY_LocalEmbedding, AFoldIsAnOverlap) {
  // Site 4 moved to (0.6, 0.3): triangle 0,5,4 turns clockwise ((0.6,0.55)×(0.6,0.3) = −0.15), so 1
  // and 4 lie on the same side of edge 0–5 (both right of it), while every count still holds.
  const auto sites = six_sites({0.6, 0.3});
  const DualTriangles T = six_triangles();
  EXPECT_EQ(embedding_failure(T, sites, square_sides), "the triangle of sites 0, 1, 5 overlaps a neighbour");
  EXPECT_TRUE(overlaps(T, 0, sites));
  EXPECT_TRUE(overlaps(T, 1, sites));
  EXPECT_FALSE(overlaps(T, 4, sites));  // 5,2,3 borders 4,5,3 and 1,2,5 only, each across its edge
}

TEST(BWY_LocalEmbedding, EachOtherFailureIsNamed) {
  DualTriangles flat = six_triangles();
  flat.add(9, {0, 1, 2}, true);
  EXPECT_EQ(embedding_failure(flat, six_sites(), square_sides), "the triangle of sites 0, 1, 2 is flat");
  EXPECT_TRUE(overlaps(flat, flat.alive().back(), six_sites()));

  auto seven = six_sites();
  seven.push_back({0.5, 0.2});
  EXPECT_EQ(embedding_failure(six_triangles(), seven, square_sides), "site 6 is a vertex of no triangle");

  // Side 0–1 as an interior segment must be in two triangles; the diagonal 0–5 as one is.
  EXPECT_EQ(embedding_failure(six_triangles(), six_sites(), {{0, 1, false}, {1, 2, true}, {2, 3, true}, {3, 0, true}}),
            "the subsegment 0–1 is in 1 triangles");
  EXPECT_EQ(embedding_failure(six_triangles(), six_sites(), {{0, 1, true}, {1, 2, true}, {2, 3, true}, {3, 0, true}, {0, 5, false}}), "");
  // The diagonal 0–5 as a boundary subsegment must be in one.
  EXPECT_EQ(embedding_failure(six_triangles(), six_sites(), {{0, 1, true}, {0, 5, true}}), "the subsegment 0–5 is in 2 triangles");
}

TEST(BWY_LocalEmbedding, RemovingAKeyReturnsTheEdgesItLeftEmpty) {
  DualTriangles T = six_triangles();
  // Triangle 0,5,4 (key 1) shares each edge with a neighbour: none is left empty, and the counts drop.
  EXPECT_TRUE(T.remove(1).empty());
  EXPECT_EQ(T.on_edge(0, 5).size(), 1u);
  EXPECT_EQ(T.alive().size(), 5u);
  // Then 0,1,5 (key 0) leaves side 0–1 and edge 0–5 in none.
  auto emptied = T.remove(0);
  std::sort(emptied.begin(), emptied.end());
  EXPECT_EQ(emptied, (std::vector<std::pair<int, int>>{{0, 1}, {0, 5}}));
}

}  // namespace
