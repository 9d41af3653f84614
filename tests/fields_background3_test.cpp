// The tetrahedral background field (fields/background3.hpp) on the Kuhn grid of 2 × 2 × 2 cubes with
// a metric linear in the coordinates at its vertices: P1 reproduces a linear field exactly, so at
// every rational point of the grid's box the value is the linear formula's (the independent
// closed form), on faces and edges shared by several tetrahedra included; outside, none.
#include "fields/background3.hpp"
#include "geometry/kuhn_grid.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using anisocert::Rational;
using anisocert::fields::BackgroundMesh3;
using anisocert::fields::BackgroundMeshError;
using anisocert::predicates::Point3;
using anisocert::predicates::Sym3;

// Positive definite on [0, 2]³ (diagonally dominant): [4 + x, y/4, 0; y/4, 5 + z, x/8; 0, x/8, 3 + x + y].
Sym3<Rational> linear(const Point3<Rational>& p) {
  return {4 + p.x, p.y / 4, 0, 5 + p.z, p.x / 8, 3 + p.x + p.y};
}

anisocert::geometry::Mesh3<Rational> grid() {
  auto m = anisocert::geometry::kuhn_grid(2);
  for (const auto& p : m.vertices) m.metrics.push_back(linear(p));
  return m;
}

TEST(Background3, ALinearFieldIsReproducedExactly) {
  const BackgroundMesh3 b(grid());
  EXPECT_EQ(b.tetrahedron_count(), 48u);
  std::mt19937 rng(39);
  std::uniform_int_distribution<int> k(0, 64);
  for (int t = 0; t < 300; ++t) {
    // Multiples of 1/32 in [0, 2]: many on the cubes' faces, the Kuhn diagonals' planes and edges.
    const Point3<Rational> p{Rational(k(rng), 32), Rational(k(rng), 32), Rational(k(rng), 32)};
    const auto M = b.metric_at(p);
    ASSERT_TRUE(M.has_value()) << t;
    EXPECT_TRUE(*M == linear(p)) << t;
  }
  EXPECT_FALSE(b.metric_at({Rational(-1, 1000000), 1, 1}).has_value());
  EXPECT_FALSE(b.metric_at({1, 1, Rational(2000001, 1000000)}).has_value());
  EXPECT_TRUE(b.metric_at({2, 2, 2}).has_value());  // a corner of the box
}

TEST(Background3, BadMeshesAreRefusedByName) {
  auto flat = grid();
  flat.vertices[flat.tetrahedra[5][3]] = flat.vertices[flat.tetrahedra[5][0]];
  const auto message = [](const anisocert::geometry::Mesh3<Rational>& m) {
    try {
      BackgroundMesh3 b(m);
    } catch (const BackgroundMeshError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(flat).find("is flat"), std::string::npos) << message(flat);
  auto indefinite = grid();
  indefinite.metrics[7] = Sym3<Rational>{-1, 0, 0, -1, 0, 1};  // det = +1, not positive definite
  EXPECT_EQ(message(indefinite), "background vertex 8 (counted from 1): its metric is not positive definite");
  auto beyond = grid();
  beyond.tetrahedra[0][2] = 1000;
  EXPECT_NE(message(beyond).find("names a vertex beyond the 27 there are"), std::string::npos);
  auto none = grid();
  none.tetrahedra.clear();
  EXPECT_EQ(message(none), "the background mesh has no tetrahedra");
}

}  // namespace
