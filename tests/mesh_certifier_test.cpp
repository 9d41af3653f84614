// The exact mesh certifier (oracle/certify/mesh_certifier.hpp) on meshes with known answers: closed-form
// radius-edge ratios and distortions, a non-Delaunay quadrilateral, cocircular ties, and broken
// triangulations (a hole, an overlap, a clockwise triangle, a segment that is not a union of edges).
#include "oracle/certify/mesh_certifier.hpp"
#include "witness_lists.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using anisocert::Rational;
using namespace anisocert::oracle;

// The unit square split at an interior point c into four triangles, identity metrics.
Mesh<Rational> fan(const Rational& cx, const Rational& cy) {
  Mesh<Rational> m;
  m.sites = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {cx, cy}};
  m.metrics.assign(5, {1, 0, 1});
  m.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  return m;
}

// Closed form: the right isosceles triangle (0,0), (1,0), (1/2,1/2) has circumradius 1/2 and
// shortest edge √2/2, ratio 1/√2 ≈ 0.7071; the fan around the centre of the unit square has four.
TEST(MeshCertifier, RadiusEdgeRatioAgainstTheClosedForm) {
  const Mesh<Rational> m = fan(Rational(1, 2), Rational(1, 2));
  CertifyOptions o;
  o.rho0 = Rational(708, 1000);
  EXPECT_TRUE(certify_mesh(m, o).rho_violations.empty());
  o.rho0 = Rational(707, 1000);
  const CertifyReport r = certify_mesh(m, o);
  EXPECT_EQ(r.rho_violations.count(), 4u);  // every triangle (one witness each: bounded reports)
  EXPECT_NEAR(r.worst_rho, 0.70710678118, 1e-9);
}

// At the bound exactly: ρ ≤ ρ₀ holds with equality, which is no violation. The right triangle
// (0,0), (4,0), (0,3) under M = I has circumradius 5/2 (half its hypotenuse, Thales) and shortest
// edge 3, so ratio 5/6 exactly; any ρ₀ below it is violated.
TEST(MeshCertifier, RadiusEdgeRatioExactlyAtTheBoundIsNoViolation) {
  Mesh<Rational> m;
  m.sites = {{0, 0}, {4, 0}, {0, 3}};
  m.metrics.assign(3, {1, 0, 1});
  m.domain = m.sites;
  m.triangles = {{0, 1, 2}};
  CertifyOptions o;
  o.rho0 = Rational(5, 6);
  EXPECT_TRUE(certify_mesh(m, o).rho_violations.empty());
  o.rho0 = Rational(5, 6) - Rational(1, 1000000000000);
  EXPECT_EQ(certify_mesh(m, o).rho_violations.count(), 1u);  // one witness per triangle
}

// Closed form: τ(I, 4I) = 2 (LS: the largest stretch between the two unit balls).
TEST(MeshCertifier, DistortionAgainstTheClosedForm) {
  Mesh<Rational> m = fan(Rational(1, 2), Rational(1, 3));
  m.metrics[4] = {4, 0, 4};
  CertifyOptions o;
  o.gamma0 = 2;
  EXPECT_TRUE(certify_mesh(m, o).gamma_violations.empty());
  o.gamma0 = Rational(199, 100);
  const CertifyReport r = certify_mesh(m, o);
  EXPECT_EQ(r.gamma_violations.count(), 4u);  // each triangle has two edges to the centre: one witness each
  EXPECT_NEAR(r.worst_gamma, 2.0, 1e-12);
}

TEST(MeshCertifier, ValidFanIsLocallyUniformAndTheSquareCentreIsATie) {
  const CertifyReport off = certify_mesh(fan(Rational(2, 5), Rational(9, 20)), {});
  EXPECT_TRUE(off.valid_holds());
  EXPECT_TRUE(off.uniform_violations.empty());
  EXPECT_TRUE(off.uniform_ties.empty());
  // Two triangles of the unit square split by a diagonal: all four corners are cocircular.
  Mesh<Rational> sq;
  sq.sites = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  sq.metrics.assign(4, {1, 0, 1});
  sq.domain = sq.sites;
  sq.triangles = {{0, 1, 2}, {0, 2, 3}};
  const CertifyReport r = certify_mesh(sq, {});
  EXPECT_TRUE(r.valid_holds());
  EXPECT_TRUE(r.uniform_violations.empty());
  EXPECT_EQ(r.uniform_ties.count(), 2u);  // each triangle's circumcircle holds the fourth corner (one witness each)
  for (const MeshWitness& w : r.uniform_ties.described()) EXPECT_EQ(w.site, w.triangle == 0 ? 3 : 1);
}

// A tie does not hide a violation: the circumcircle of the triangle (0,0), (1,0), (1,1) passes
// through the corner (0,1) and holds the site (1/5, 4/5) strictly inside ((3/10)² + (3/10)² < 1/2),
// so that triangle is a violation whichever of the two sites the search meets first. The
// configuration is turned four ways and mirrored, so that the search meets them in both orders.
TEST(MeshCertifier, TieFoundFirstDoesNotHideAViolation) {
  for (int mirror = 0; mirror < 2; ++mirror)
    for (int turn = 0; turn < 4; ++turn) {
      Mesh<Rational> m;
      m.sites = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {Rational(1, 5), Rational(4, 5)}};
      m.triangles = {{0, 1, 2}, {0, 2, 4}, {2, 3, 4}, {3, 0, 4}};
      for (auto& p : m.sites) {
        for (int k = 0; k < turn; ++k) p = {1 - p.y, p.x};  // a quarter turn about (1/2, 1/2)
        if (mirror) p.x = 1 - p.x;
      }
      if (mirror)
        for (auto& t : m.triangles) std::swap(t[1], t[2]);  // counter-clockwise again
      m.metrics.assign(5, {1, 0, 1});
      m.domain = {m.sites[0], m.sites[1], m.sites[2], m.sites[3]};
      if (mirror) std::reverse(m.domain.begin(), m.domain.end());
      const CertifyReport r = certify_mesh(m, {});
      SCOPED_TRACE("turn " + std::to_string(turn) + (mirror ? ", mirrored" : ""));
      EXPECT_TRUE(r.valid_holds());
      const auto strict = r.uniform_violations.described();
      EXPECT_TRUE(std::any_of(strict.begin(), strict.end(), [](const MeshWitness& w) { return w.triangle == 0 && w.site == 4; }));
    }
}

// A quadrilateral split by its long diagonal: the other vertex is inside the circumcircle.
TEST(MeshCertifier, NonDelaunayDiagonalIsAViolationWithWitness) {
  Mesh<Rational> m;
  m.sites = {{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  m.metrics.assign(4, {1, 0, 1});
  m.sites[2] = {3, 1};
  m.domain = m.sites;
  m.triangles = {{0, 1, 2}, {0, 2, 3}};  // diagonal (0,0)-(3,1)
  CertifyReport r = certify_mesh(m, {});
  EXPECT_TRUE(r.valid_holds());
  EXPECT_TRUE(r.uniform_violations.empty()) << "this diagonal is the Delaunay one";
  m.triangles = {{0, 1, 3}, {1, 2, 3}};  // diagonal (4,0)-(0,1): (3,1) lies inside circle (0,0),(4,0),(0,1)
  r = certify_mesh(m, {});
  EXPECT_TRUE(r.valid_holds());
  ASSERT_FALSE(r.uniform_violations.empty());
  EXPECT_EQ(r.uniform_violations.described()[0].triangle, 0);
  EXPECT_EQ(r.uniform_violations.described()[0].site, 2);
  // In the metric M = FᵀF of the shear F = [1 3; 0 1] the first diagonal is no longer the Delaunay
  // one: F maps the corners to (0,0), (4,0), (6,1), (3,1), and (3,1) lies inside the circle through
  // the other three (centre (2, 13/2), r² = 185/4 > 125/4 = |(3,1) − centre|²). Metrics matter.
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.metrics.assign(4, {1, 3, 10});
  r = certify_mesh(m, {});
  ASSERT_FALSE(r.uniform_violations.empty());
  EXPECT_EQ(r.uniform_violations.described()[0].site, 3);
}

TEST(MeshCertifier, BrokenTriangulationsAreRejectedByName) {
  Mesh<Rational> hole = fan(Rational(1, 2), Rational(1, 3));
  hole.triangles.pop_back();
  CertifyReport r = certify_mesh(hole, {});
  EXPECT_FALSE(r.valid_holds());
  Mesh<Rational> clockwise = fan(Rational(1, 2), Rational(1, 3));
  std::swap(clockwise.triangles[0][0], clockwise.triangles[0][1]);
  r = certify_mesh(clockwise, {});
  ASSERT_FALSE(r.valid_holds());
  EXPECT_NE(r.valid->failures[0].find("triangle 0"), std::string::npos) << r.valid->failures[0];
  Mesh<Rational> overlap = fan(Rational(1, 2), Rational(1, 3));
  overlap.triangles.push_back({0, 1, 4});
  EXPECT_FALSE(certify_mesh(overlap, {}).valid_holds());
  Mesh<Rational> segment = fan(Rational(1, 2), Rational(1, 3));
  segment.segments = {{0, 2}};  // the diagonal is not an edge
  r = certify_mesh(segment, {});
  ASSERT_EQ(r.segment_failure_count, 1u);
  ASSERT_EQ(r.segment_failures.size(), 1u);
  segment.segments = {{0, 4}};  // a spoke is
  EXPECT_TRUE(certify_mesh(segment, {}).valid_holds());
}

}  // namespace

namespace {

// A k×k lattice with rational jitter, quads split along alternating diagonals: about half of them
// the non-Delaunay one, and unjittered squares on the boundary give exact ties.
Mesh<Rational> alternating_lattice(int k) {
  Mesh<Rational> m;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const bool boundary = i == 0 || j == 0 || i == k || j == k;
      m.sites.push_back({Rational(i) + (boundary ? Rational(0) : Rational((i * 7 + j * 3) % 5 - 2, 20)),
                         Rational(j) + (boundary ? Rational(0) : Rational((i * 2 + j * 5) % 7 - 3, 30))});
    }
  m.metrics.assign(m.sites.size(), {4, 1, 1});
  auto at = [&](int i, int j) { return j * (k + 1) + i; };
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2 == 0) m.triangles.push_back({a, b, c}), m.triangles.push_back({a, c, d});
      else m.triangles.push_back({a, b, d}), m.triangles.push_back({b, c, d});
    }
  m.domain = {{0, 0}, {k, 0}, {k, k}, {0, k}};
  return m;
}

}  // namespace

// Issue 14: the locally uniform check runs per triangle on every core; its findings are added in
// triangle order, so the report is the one thread's, witness for witness.
TEST(MeshCertifier, UniformCheckOnTwoThreadsGivesTheOneThreadReport) {
  const Mesh<Rational> m = alternating_lattice(12);
  CertifyOptions o;
  o.valid = false;
  o.threads = 1;
  const CertifyReport one = certify_mesh(m, o);
  o.threads = 2;
  const CertifyReport two = certify_mesh(m, o);
  ASSERT_GT(one.uniform_violations.count(), 10u) << "the lattice must have violations for this test to mean anything";
  EXPECT_EQ(one.incircle_tests, two.incircle_tests);
  expect_same_witnesses(one.uniform_violations, two.uniform_violations, "violations");
  expect_same_witnesses(one.uniform_ties, two.uniform_ties, "ties");
}

// Every constrained segment is a union of edges, the sites on it ordered by their exact parameter
// along it: sites 4 = (1, 0), 5 = (2, 0), 6 = (3, 0) on the segment 4–6, and triangles that join 4–5
// but not 5–6 (the edge (5/2, −1)–(5/2, 1) crosses between them). The check names 5 and 6. (A
// version whose parameter was off by a factor that grows with the segment's x dropped site 6 as
// beyond the segment and passed it: the 2026-12-02 campaign.)
TEST(MeshCertifier, ASegmentWithAGapBetweenItsSitesIsNamed) {
  Mesh<Rational> m;
  m.sites = {{0, -1}, {4, -1}, {4, 1}, {0, 1}, {1, 0}, {2, 0}, {3, 0}, {Rational(5, 2), -1}, {Rational(5, 2), 1}};
  m.triangles = {{0, 4, 3}, {0, 7, 5}, {0, 5, 4}, {4, 5, 3}, {5, 8, 3}, {5, 7, 8}, {7, 1, 6}, {7, 6, 8}, {6, 1, 2}, {6, 2, 8}};
  m.segments = {{4, 6}};
  CertifyOptions o;
  o.uniform = false;
  const CertifyReport r = certify_mesh(m, o);
  ASSERT_TRUE(r.valid);
  EXPECT_TRUE(r.valid->is_triangulation);
  ASSERT_EQ(r.segment_failure_count, 1u);
  EXPECT_NE(r.segment_failures[0].find("sites 5 and 6 are consecutive on it but not joined by an edge"), std::string::npos)
      << r.segment_failures[0];
}
