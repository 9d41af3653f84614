// The exact certifier of tetrahedral meshes (oracle/certify/mesh_certifier3.hpp) on meshes whose
// answers are known by hand: Kuhn-subdivided grids of unit cubes (each cube's six tetrahedra share
// its circumsphere, on which its eight corners lie and no other grid point: distances² from the
// centre are Σ (k − 1/2)², 3/4 only for k ∈ {0, 1}), two tetrahedra across a face that break the
// Delaunay condition, and metric lengths at the exact boundary √2.

#include "oracle/certify/mesh_certifier3.hpp"
#include "predicates/orientation3.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using anisocert::Rational;
using anisocert::Sign;
using namespace anisocert::oracle;
using Mesh3 = anisocert::geometry::Mesh3<Rational>;
using anisocert::predicates::Sym3;

namespace {

int vertex(Mesh3& m, int x, int y, int z) {
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    if (m.vertices[i].x == x && m.vertices[i].y == y && m.vertices[i].z == z) return static_cast<int>(i);
  m.vertices.push_back({x, y, z});
  return static_cast<int>(m.vertices.size() - 1);
}

// The n × n × n grid of unit cubes, each in its six Kuhn tetrahedra, positively oriented; metric M
// everywhere.
Mesh3 kuhn_grid(int n, const Sym3<Rational>& M) {
  Mesh3 m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::array<int, 3> axes{0, 1, 2};
        do {
          std::array<int, 3> p{i, j, k};
          std::array<int, 4> t{};
          t[0] = vertex(m, p[0], p[1], p[2]);
          for (std::size_t s = 0; s < 3; ++s) ++p[static_cast<std::size_t>(axes[s])], t[s + 1] = vertex(m, p[0], p[1], p[2]);
          const auto& v = m.vertices;
          if (anisocert::predicates::orientation3(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) == Sign::negative) std::swap(t[2], t[3]);
          m.tetrahedra.push_back(t);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  m.metrics.assign(m.vertices.size(), M);
  return m;
}

Certify3Options all_checks() {
  Certify3Options o;
  o.metric = true;
  return o;
}

}  // namespace

// 2 × 2 × 2 cubes: 48 tetrahedra, valid; locally uniform with every test a tie or outside: each
// tetrahedron's sphere holds the other four corners of its cube, and nothing else. One witness
// per tetrahedron, as in 2D: 48 ties (one each, the first found), no violation.
TEST(MeshCertifier3, TheKuhnGridIsValidAndDelaunayWithTies) {
  const Mesh3 m = kuhn_grid(2, {1, 0, 0, 1, 0, 1});
  const Certify3Report r = certify_mesh3(m, all_checks());
  ASSERT_TRUE(r.valid);
  EXPECT_TRUE(r.valid_holds());
  EXPECT_EQ(r.tetrahedra, 48u);
  EXPECT_TRUE(r.uniform_checked);
  EXPECT_EQ(r.uniform_violations.count(), 0u);
  EXPECT_EQ(r.uniform_ties.count(), 48u);
  EXPECT_TRUE(r.holds(all_checks()));
  // The same grid stretched by M = diag(1, 4, 9) in every metric, its coordinates divided by
  // (1, 2, 3): the picture is the Euclidean one, ties included.
  Mesh3 s = m;
  for (auto& p : s.vertices) p.y /= 2, p.z /= 3;
  s.metrics.assign(s.vertices.size(), Sym3<Rational>{1, 0, 0, 4, 0, 9});
  const Certify3Report t = certify_mesh3(s, all_checks());
  EXPECT_EQ(t.uniform_violations.count(), 0u);
  EXPECT_EQ(t.uniform_ties.count(), 48u);
}

// Two tetrahedra across the face (0,0,0), (1,0,0), (0,1,0): apexes (0,0,1) and (3/10, 3/10, −1/10).
// The first one's sphere (centre (1/2, 1/2, 1/2), radius² 3/4) holds the second apex (distance²
// 0.44), and then the second's holds the first apex (the in-sphere test of five points does not
// depend on which four make the tetrahedron, up to orientation): each tetrahedron has one vertex
// inside, named once (its search stops there): 2 violations. The mesh is valid.
TEST(MeshCertifier3, AFaceThatShouldFlipIsNamedFromBothSides) {
  Mesh3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {Rational(3, 10), Rational(3, 10), Rational(-1, 10)}};
  m.tetrahedra = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  m.metrics.assign(5, Sym3<Rational>{1, 0, 0, 1, 0, 1});
  const Certify3Report r = certify_mesh3(m, all_checks());
  EXPECT_TRUE(r.valid_holds());
  EXPECT_EQ(r.uniform_violations.count(), 2u);
  EXPECT_EQ(r.uniform_ties.count(), 0u);
  ASSERT_FALSE(r.uniform_violations.described().empty());
  EXPECT_NE(r.uniform_violations.described()[0].text.find("strictly inside the circumsphere of tetrahedron 0"), std::string::npos);
  EXPECT_FALSE(r.holds(all_checks()));
  // A metric that squashes z by 1/100 (M = diag(1, 1, 10⁴)) keeps every sphere thin in z: the
  // apex at z = −1/10 is then far outside the first tetrahedron's ellipsoid in its vertices' metrics.
  m.metrics.assign(5, Sym3<Rational>{1, 0, 0, 1, 0, 10000});
  const Certify3Report s = certify_mesh3(m, all_checks());
  EXPECT_EQ(s.uniform_violations.count(), 0u);
  // Every vertex's own metric is asked: with M = I at vertex 2 only (third in the first
  // tetrahedron, second in the other), each tetrahedron is caught in vertex 2's metric alone.
  m.metrics[2] = Sym3<Rational>{1, 0, 0, 1, 0, 1};
  const Certify3Report u = certify_mesh3(m, all_checks());
  ASSERT_EQ(u.uniform_violations.count(), 2u);
  for (const auto& w : u.uniform_violations.described()) EXPECT_EQ(w.vertex, 2) << w.text;
}

// One Kuhn cube, M = I: its 19 edges are the 12 cube edges (length 1), 6 face diagonals (√2,
// exactly the upper end of [1/√2, √2], which is closed) and the diagonal (√3): 18 unit edges.
// With M = I/2 (lengths ÷ √2) the diagonals √3/√2 ≈ 1.22 are in and the cube edges 1/√2 are too
// (exactly the lower end): 19.
TEST(MeshCertifier3, UnitEdgesAreDecidedExactlyAtTheEnds) {
  Mesh3 m = kuhn_grid(1, {1, 0, 0, 1, 0, 1});
  const Certify3Report r = certify_mesh3(m, all_checks());
  ASSERT_TRUE(r.lengths);
  EXPECT_EQ(r.lengths->edges, 19u);
  EXPECT_EQ(r.lengths->unit_edges, 18u);
  m.metrics.assign(m.vertices.size(), Sym3<Rational>{Rational(1, 2), 0, 0, Rational(1, 2), 0, Rational(1, 2)});
  const Certify3Report h = certify_mesh3(m, all_checks());
  EXPECT_EQ(h.lengths->unit_edges, 19u);
  // A range as a verdict: [1, 1] in M = I holds for the 12 cube edges only.
  Certify3Options o = all_checks();
  o.length_range = {Rational(1), Rational(1)};
  m.metrics.assign(m.vertices.size(), Sym3<Rational>{1, 0, 0, 1, 0, 1});
  const Certify3Report g = certify_mesh3(m, o);
  EXPECT_EQ(g.lengths->range_violations.count(), 7u);
  EXPECT_FALSE(g.holds(o));
}
