// The exact diagram (oracle/diagram/diagram.hpp) against independent methods: closed forms for
// multiplicatively weighted sites (M = w·I: bisectors are Apollonius circles), brute-force exact
// sampling (the nearest-site set of a rational point, computed from the definition, must equal
// the owners of whatever the oracle says contains it), and degenerate fixtures with known answers.
#include "oracle/diagram/diagram.hpp"
#include "tests/brute_force.hpp"
#include "tests/checked_diagram.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace {

using anisocert::Rational;
using namespace anisocert::oracle;
using anisocert::test_support::checked_diagram;
using anisocert::test_support::expect_brute_force_agrees;

Mesh<Rational> square_input(const Rational& lo, const Rational& hi) {
  Mesh<Rational> in;
  in.domain = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  return in;
}

void add_site(Mesh<Rational>& in, Rational x, Rational y, Rational m11, Rational m12, Rational m22) {
  in.sites.push_back({x, y});
  in.metrics.push_back({m11, m12, m22});
}

int count_kind(const Diagram& d, Node::Kind k) {
  return static_cast<int>(std::count_if(d.nodes.begin(), d.nodes.end(), [&](const Node& n) { return n.kind == k; }));
}

// Closed form: w_v|p − v|² = w_w|p − w|² is the circle with centre (w_v v − w_w w)/(w_v − w_w) and
// radius² w_v w_w |v − w|²/(w_v − w_w)²: v = (0,0), w_v = 4, w = (3,0), w_w = 1 gives centre (−1, 0),
// radius 2, around v. The heavier site's cell is the disc: an island bounded by a closed arc.
TEST(OracleDiagram, WeightedPairIsAnIslandBoundedByTheApolloniusCircle) {
  Mesh<Rational> in = square_input(-5, 5);
  add_site(in, 0, 0, 4, 0, 4);
  add_site(in, 3, 0, 1, 0, 1);
  const Diagram d = checked_diagram(in);
  ASSERT_EQ(d.arcs.size(), 1u);
  EXPECT_TRUE(d.arcs[0].closed);
  EXPECT_EQ(count_kind(d, Node::Kind::voronoi), 0);
  ASSERT_EQ(d.faces.size(), 2u);
  for (const Face& f : d.faces) EXPECT_FALSE(f.orphan);
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{1, 0}, {-3, 0}, {-1, 2}, {-1, -2}}) {
    const Location loc = locate(d, {x, y});  // the circle's extreme points
    EXPECT_EQ(loc.kind, Location::Kind::arc) << x << "," << y;
    EXPECT_EQ(loc.owners, (std::vector<int>{0, 1}));
  }
  EXPECT_EQ(locate(d, {Rational(99, 100), 0}).owners, std::vector<int>{0});  // just inside
  EXPECT_EQ(locate(d, {Rational(101, 100), 0}).owners, std::vector<int>{1});  // just outside
  expect_brute_force_agrees(d, 20);
}

// Three weighted sites: circles meeting at vertices, cells bounded by circular arcs.
TEST(OracleDiagram, WeightedTriplesAgreeWithBruteForce) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(1, 19), weight(1, 6);
  for (int trial = 0; trial < 12; ++trial) {
    SCOPED_TRACE(trial);
    Mesh<Rational> in = square_input(0, 1);
    for (int i = 0; i < 4; ++i) {
      const Rational w = weight(rng);
      add_site(in, Rational(coord(rng), 20), Rational(coord(rng), 20), w, 0, w);
    }
    std::sort(in.sites.begin(), in.sites.end(), [](auto& a, auto& b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
    in.sites.erase(std::unique(in.sites.begin(), in.sites.end(),
                               [](auto& a, auto& b) { return a.x == b.x && a.y == b.y; }),
                   in.sites.end());
    in.metrics.resize(in.sites.size());
    const Diagram d = checked_diagram(in);
    expect_brute_force_agrees(d, 16);
  }
}

// Anisotropic random inputs (metrics with anisotropy up to about 10:1): brute force everywhere.
TEST(OracleDiagram, AnisotropicInputsAgreeWithBruteForce) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coord(1, 39), entry(-9, 9), diag(1, 10);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE(trial);
    Mesh<Rational> in = square_input(0, 1);
    for (int i = 0; i < 6 + trial; ++i) {
      // M = FᵀF with F = [[a, b], [0, c]] is positive definite for a, c ≠ 0.
      const Rational a(diag(rng)), b(entry(rng)), c(diag(rng));
      in.sites.push_back({Rational(coord(rng), 40), Rational(coord(rng), 40)});
      in.metrics.push_back({a * a, a * b, b * b + c * c});
    }
    std::vector<int> keep;
    for (std::size_t i = 0; i < in.sites.size(); ++i) {
      bool dup = false;
      for (int j : keep) dup = dup || (in.sites[j].x == in.sites[i].x && in.sites[j].y == in.sites[i].y);
      if (!dup) keep.push_back(static_cast<int>(i));
    }
    Mesh<Rational> clean = square_input(0, 1);
    for (int i : keep) clean.sites.push_back(in.sites[i]), clean.metrics.push_back(in.metrics[i]);
    const Diagram d = checked_diagram(clean);
    expect_brute_force_agrees(d, 24);
    // Every site lies in exactly one face of its own cell that is not an orphan (LS Definition 1).
    for (std::size_t s = 0; s < clean.sites.size(); ++s)
      EXPECT_EQ(std::count_if(d.faces.begin(), d.faces.end(),
                              [&](const Face& f) { return f.site == static_cast<int>(s) && !f.orphan; }),
                1);
  }
}

// Degenerate: four cocircular sites (identity metric) at the corners of a diamond domain: one
// vertex of degree 4 at the centre, its dual a convex quadrilateral, which polygonalizes Ω
// (LS Theorem 7 with its preconditions met: corners are sites, each cut arc is owned by its edge).
// LS Theorem 7 assumes the sites lie in Ω. Regression: `anisocert dual` on a stopped LS run (six
// corners of an L, one triangle) took Ω as that triangle; the three sites outside it owned arcs
// across its edges, the dual was no triangulation, and the preconditions were reported to hold
// ("conclusion CONTRADICTED").
TEST(OracleDiagram, SitesOutsideOmegaFailTheorem7sPreconditions) {
  Mesh<Rational> in;
  in.domain = {{Rational(1, 2), Rational(1, 2)}, {Rational(1, 2), 1}, {0, 1}};
  add_site(in, Rational(1, 2), Rational(1, 2), 1, 0, 1);
  add_site(in, Rational(1, 2), 1, 1, 0, 1);
  add_site(in, 0, 1, 1, 0, 1);
  add_site(in, 0, 0, 1, 0, 1);  // outside the triangle
  const Diagram d = compute_diagram(in);
  EXPECT_FALSE(d.theorem7.preconditions_hold);
  EXPECT_FALSE(d.theorem7.disagreement);
  EXPECT_TRUE(std::any_of(d.theorem7.reasons.begin(), d.theorem7.reasons.end(),
                          [](const std::string& r) { return r == "site 3 lies outside Ω"; }));
}

TEST(OracleDiagram, CocircularSitesGiveOneVertexOfDegreeFour) {
  Mesh<Rational> in;
  in.domain = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (const auto& p : in.domain) add_site(in, p.x, p.y, 1, 0, 1);
  const Diagram d = checked_diagram(in);
  ASSERT_EQ(count_kind(d, Node::Kind::voronoi), 1);
  const Location centre = locate(d, {0, 0});
  ASSERT_EQ(centre.kind, Location::Kind::node);
  EXPECT_EQ(centre.owners, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(d.dual_triangles.empty());
  ASSERT_EQ(d.dual_polygons.size(), 1u);
  EXPECT_EQ(d.dual_polygons[0].sites, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(d.theorem7.preconditions_hold);
  EXPECT_TRUE(d.dual_check.is_triangulation);
  EXPECT_EQ(d.arcs.size(), 4u);
  expect_brute_force_agrees(d, 16);
}

// Degenerate: the circumcentre (0, 0) of three sites at distance 1 lies exactly on ∂Ω.
TEST(OracleDiagram, VertexExactlyOnTheDomainBoundary) {
  Mesh<Rational> in;
  in.domain = {{-2, 0}, {2, 0}, {2, 2}, {-2, 2}};
  add_site(in, Rational(-3, 5), Rational(4, 5), 1, 0, 1);
  add_site(in, Rational(3, 5), Rational(4, 5), 1, 0, 1);
  add_site(in, 0, 1, 1, 0, 1);
  const Diagram d = checked_diagram(in);
  const Location loc = locate(d, {0, 0});
  ASSERT_EQ(loc.kind, Location::Kind::node);
  EXPECT_EQ(loc.owners, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(d.nodes[loc.index].kind, Node::Kind::voronoi);
  EXPECT_EQ(d.nodes[loc.index].boundary_edges, std::vector<int>{0});
  expect_brute_force_agrees(d, 16);
}

// Degenerate: the Apollonius circle (centre (1, 0), radius 2) of v = (0,0), w_v = 4 and
// w = (−3, 0), w_w = 1 touches the top edge y = 2 of Ω at (1, 2): the arc runs from that point
// around and back to it, and both cells stay connected.
TEST(OracleDiagram, ArcTangentToTheDomainBoundary) {
  Mesh<Rational> in;
  in.domain = {{-4, -4}, {4, -4}, {4, 2}, {-4, 2}};
  add_site(in, 0, 0, 4, 0, 4);
  add_site(in, -3, 0, 1, 0, 1);
  const Diagram d = checked_diagram(in);
  const Location touch = locate(d, {1, 2});
  ASSERT_EQ(touch.kind, Location::Kind::node);
  EXPECT_EQ(touch.owners, (std::vector<int>{0, 1}));
  ASSERT_EQ(d.arcs.size(), 1u);
  EXPECT_FALSE(d.arcs[0].closed);
  EXPECT_EQ(d.arcs[0].ends[0], d.arcs[0].ends[1]);
  EXPECT_EQ(d.faces.size(), 2u);
  for (const Face& f : d.faces) EXPECT_FALSE(f.orphan);
  expect_brute_force_agrees(d, 24);
}

// Degenerate: a vertex exactly on a wedge line. v = (−1, 0), M_v = I; w = (−1, 1), M_w = I/2;
// u = (4/5, −3/5), M_u = I: all at squared distance 1 from (0, 0), and (0 − v)ᵀM_v(w − v) = 0, so
// the vertex is on the boundary of wedge(v, w), which is open: not wedged (LS Definitions 2–3).
TEST(OracleDiagram, VertexExactlyOnAWedgeLineIsNotWedged) {
  Mesh<Rational> in = square_input(-3, 3);
  add_site(in, -1, 0, 1, 0, 1);
  add_site(in, -1, 1, Rational(1, 2), 0, Rational(1, 2));
  add_site(in, Rational(4, 5), Rational(-3, 5), 1, 0, 1);
  const Diagram d = checked_diagram(in);
  const Location loc = locate(d, {0, 0});
  ASSERT_EQ(loc.kind, Location::Kind::node);
  EXPECT_EQ(loc.owners, (std::vector<int>{0, 1, 2}));
  EXPECT_FALSE(d.nodes[loc.index].wedged);
  EXPECT_EQ(d.nodes[loc.index].unwedged_pair, std::make_pair(0, 1));
  // Tilting M_v to m12 = 1/10 keeps Q_v(0, 0) = 1 and makes (0 − v)ᵀM_v(w − v) = 1/10 > 0; the
  // other five wedge forms at (0, 0) are 1/2, 1.74, 1.8, 1.7 and 2.4: now the vertex is wedged.
  in.metrics[0] = {1, Rational(1, 10), 1};
  const Diagram e = checked_diagram(in);
  const Location moved = locate(e, {0, 0});
  ASSERT_EQ(moved.kind, Location::Kind::node);
  EXPECT_TRUE(e.nodes[moved.index].wedged);
  expect_brute_force_agrees(d, 18);
}

// A vertex where one cell meets itself: s0 = (1, 0) with M = I, s1 = (1, −1) with [[2, 1], [1, 1]],
// s2 = (1/2, −1/2) with 2I are all at squared distance 1 from the origin (1; 2 − 2 + 1; 2(1/4 + 1/4)),
// and around it the cells come counter-clockwise as 0, 1, 0, 2 (an independent reader's drawing,
// issue 38). The listing of a cycle is its least rotation, [0, 1, 0, 2], whichever way the input
// is placed: the half-turn x ↦ −x keeps every distance (Mv = M(−v) under v ↦ −v) and the
// counter-clockwise order, so it must list the same. Rotating to the least site alone gave
// [0, 2, 0, 1] after the half-turn (mutant 49 of the 2026-11-30 campaign showed it).
TEST(OracleDiagram, PolygonOfACellMeetingItselfIsListedTheSameAfterAHalfTurn) {
  for (const int turn : {1, -1}) {
    Mesh<Rational> in = square_input(-3, 3);
    add_site(in, turn, 0, 1, 0, 1);
    add_site(in, turn, -turn, 2, 1, 1);
    add_site(in, Rational(turn, 2), Rational(-turn, 2), 2, 0, 2);
    const Diagram d = checked_diagram(in);
    const Location loc = locate(d, {0, 0});
    ASSERT_EQ(loc.kind, Location::Kind::node);
    const auto at_origin = std::find_if(d.dual_polygons.begin(), d.dual_polygons.end(),
                                        [&](const DualCell& c) { return c.vertex == loc.index; });
    ASSERT_NE(at_origin, d.dual_polygons.end()) << "half-turn " << (turn < 0);
    EXPECT_EQ(at_origin->sites, (std::vector<int>{0, 1, 0, 2})) << "half-turn " << (turn < 0);
  }
}

// A single site owns Ω; two sites with equal metrics have a straight bisector.
TEST(OracleDiagram, OneAndTwoSites) {
  Mesh<Rational> one = square_input(0, 1);
  add_site(one, Rational(1, 3), Rational(1, 3), 2, 1, 3);
  const Diagram d1 = checked_diagram(one);
  EXPECT_EQ(d1.faces.size(), 1u);
  EXPECT_TRUE(d1.arcs.empty());
  EXPECT_FALSE(d1.dual_check.is_triangulation);
  Mesh<Rational> two = square_input(0, 1);
  add_site(two, Rational(1, 4), Rational(1, 2), 1, 0, 1);
  add_site(two, Rational(3, 4), Rational(1, 2), 1, 0, 1);
  const Diagram d2 = checked_diagram(two);
  ASSERT_EQ(d2.arcs.size(), 1u);
  EXPECT_EQ(d2.arcs[0].cut_by_edges, (std::vector<int>{0, 2}));
  EXPECT_EQ(locate(d2, {Rational(1, 2), Rational(1, 3)}).kind, Location::Kind::arc);
  expect_brute_force_agrees(d2, 8);
}

}  // namespace

namespace {

// A non-convex (L-shaped) domain with a site on its reflex corner and anisotropic metrics: the
// restriction may cut cells into several faces; brute force decides every grid point.
TEST(OracleDiagram, NonConvexDomainAgreesWithBruteForce) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coord(1, 31), entry(-3, 3), diag(1, 5);
  for (int trial = 0; trial < 6; ++trial) {
    SCOPED_TRACE(trial);
    Mesh<Rational> in;
    in.domain = {{0, 0}, {1, 0}, {1, Rational(1, 2)}, {Rational(1, 2), Rational(1, 2)}, {Rational(1, 2), 1}, {0, 1}};
    add_site(in, Rational(1, 2), Rational(1, 2), 1, 0, 1);  // the reflex corner
    while (in.sites.size() < 7) {
      const Point2<Rational> p{Rational(coord(rng), 32), Rational(coord(rng), 32)};
      if (p.x > Rational(1, 2) && p.y > Rational(1, 2)) continue;  // outside the L
      bool dup = false;
      for (const auto& s : in.sites) dup = dup || (s.x == p.x && s.y == p.y);
      if (dup) continue;
      const Rational a(diag(rng)), b(entry(rng)), c(diag(rng));
      add_site(in, p.x, p.y, a * a, a * b, b * b + c * c);
    }
    const Diagram d = checked_diagram(in);
    expect_brute_force_agrees(d, 32);
    for (std::size_t s = 0; s < in.sites.size(); ++s)
      EXPECT_EQ(std::count_if(d.faces.begin(), d.faces.end(),
                              [&](const Face& f) { return f.site == static_cast<int>(s) && !f.orphan; }),
                1);
  }
}

}  // namespace

namespace {

// A degeneracy the oracle declines by name: v = (0, 1), w = (0, −1) with M = I and u = (−1, 2)
// with M_u = [1 1/2; 1/2 1/2] all have Q = t² + 1 on the x-axis (Q_u(t, 0) = (t + 1)² − 2(t + 1)
// + 2 = t² + 1), so three cells tie along a whole line (a one-dimensional piece of a cell, which
// the face structure does not model): an std::domain_error naming the three sites, never a
// wrong answer.
TEST(OracleDiagram, ThreeSitesTiedAlongALineAreDeclinedByName) {
  Mesh<Rational> in = square_input(-3, 3);
  add_site(in, 0, 1, 1, 0, 1);
  add_site(in, 0, -1, 1, 0, 1);
  add_site(in, -1, 2, 1, Rational(1, 2), Rational(1, 2));
  try {
    checked_diagram(in);
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("sites 0, 1 and 2"), std::string::npos) << e.what();
  }
}

}  // namespace

namespace {

// The genuine case stays declined, by name: two sites alone tie along the reflex edge x = 2.
TEST(OracleDiagram, ACellBoundaryAlongTheDomainBoundaryIsDeclinedByName) {
  Mesh<Rational> L;
  L.domain = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  add_site(L, 1, 1, 1, 0, 1);
  add_site(L, 3, 1, 1, 0, 1);
  try {
    checked_diagram(L);
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& err) {
    EXPECT_NE(std::string(err.what()).find("runs along domain edge 3"), std::string::npos) << err.what();
  }
}

}  // namespace
