// The triangulation check's convexity test on a polygonal cell (oracle/certify/triangulation_check.hpp):
// a cell must turn left at every vertex *and* its edge direction must turn once around. The
// pentagram of a convex pentagon turns left at every vertex but winds twice.
#include "oracle/certify/triangulation_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using anisocert::Rational;
using namespace anisocert::oracle;

// The convex pentagon (0,0), (2,0), (3,2), (1,3), (−1,2) as the domain, with one cell through its
// corners in the given order, checked.
TriangulationCheck check_one_cell(const std::vector<int>& order) {
  anisocert::geometry::Mesh<Rational> m;
  m.sites = {{0, 0}, {2, 0}, {3, 2}, {1, 3}, {-1, 2}};  // convex, counter-clockwise
  m.metrics.assign(5, {1, 0, 1});
  m.domain = m.sites;
  CellList c;
  c.add(order.data(), order.size());
  c.name = [](std::size_t k) { return "cell " + std::to_string(k); };
  return check_triangulation(EnclosedMesh(m), c);
}

bool names_non_convex(const TriangulationCheck& t) {
  return std::any_of(t.failures.begin(), t.failures.end(),
                     [](const std::string& f) { return f.find("is not strictly convex") != std::string::npos; });
}

TEST(TriangulationCheck, ConvexPentagonIsACell) {
  const TriangulationCheck t = check_one_cell({0, 1, 2, 3, 4});
  EXPECT_TRUE(t.is_triangulation);
  EXPECT_FALSE(names_non_convex(t));
}

// The cell 0, 2, 4, 1, 3 turns left at every vertex (cross products 8, 8, 7, 6, 7) and its edge
// direction turns twice around: not strictly convex, and said so (it fails other checks too: its
// edges are not the domain's).
TEST(TriangulationCheck, PentagramTurningLeftEverywhereIsNotConvex) {
  const TriangulationCheck t = check_one_cell({0, 2, 4, 1, 3});
  EXPECT_FALSE(t.is_triangulation);
  EXPECT_TRUE(names_non_convex(t));
  ASSERT_FALSE(t.bad_cells.empty());
  EXPECT_EQ(t.bad_cells.front(), 0);
}

}  // namespace
