// Properties of the exact diagram (oracle/diagram/diagram.hpp) on random inputs, named by CATALOG ID:
// LS.D1 (the faces, arcs and vertices are the minimization diagram: exact brute force at random
// rational points), LS.T4 (a face whose boundary is wedged is star-shaped from its site, hence
// no orphan), LS.L6 (a wedged vertex's dual triangle is positively oriented), LS.T7 (the
// preconditions imply that the dual is a triangulation of Ω, checked exactly).
#include "oracle/diagram/diagram.hpp"
#include "predicates/orientation.hpp"
#include "property_tests/generators/diagram_inputs.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

using anisocert::Rational;
using namespace anisocert::oracle;
using namespace anisocert::gen;

namespace {

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

// The diagram, or a discarded case when the oracle declines a one-dimensional tie by name
// (docs/oracle.md § Limits; RapidCheck counts discards and fails if they dominate).
Diagram diagram_or_discard(const Mesh<Rational>& in) {
  try {
    return compute_diagram(in);
  } catch (const std::domain_error& e) {
    RC_DISCARD(e.what());
  }
}

}  // namespace

// LS Definition 1: p lies in the cell of v iff no site is closer. The oracle's location of a
// random rational point must be owned by exactly its nearest sites.
RC_GTEST_PROP(LS_D1, LocationsAreTheNearestSites, ()) {
  const DiagramCase c = *diagram_case();
  RC_TAG(c.kind);
  const Diagram d = diagram_or_discard(c.input);
  const auto points = *rc::gen::container<std::vector<std::pair<int, int>>>(
      20, rc::gen::pair(rc::gen::inRange(0, 129), rc::gen::inRange(0, 129)));
  for (const auto& [i, j] : points) {
    const Point2<Rational> p{Rational(i, 128), Rational(j, 128)};
    RC_ASSERT(locate(d, p).owners == nearest_sites(c.input, p));
  }
}

// LS Theorem 4: if every arc and vertex on the boundary of a face of Vor(v) is wedged, the face
// is star-shaped from v (Ω is convex here, so the restriction keeps that); in particular it
// contains v: an orphan always has an unwedged arc or vertex on its boundary.
RC_GTEST_PROP(LS_T4, FacesWithWedgedBoundaryAreStarShaped, ()) {
  const DiagramCase c = *diagram_case();
  const Diagram d = diagram_or_discard(c.input);
  std::vector<bool> wedged_boundary(d.faces.size(), true);
  for (std::size_t f = 0; f < d.faces.size(); ++f) {
    std::vector<int> cycles{d.faces[f].outer_cycle};
    cycles.insert(cycles.end(), d.faces[f].holes.begin(), d.faces[f].holes.end());
    for (int cy : cycles)
      for (int h : d.cycles[cy].half_edges) {
        const HalfEdge& e = d.half_edges[h];
        if (e.arc >= 0 && !d.arcs[e.arc].wedged) wedged_boundary[f] = false;
        if (e.target >= 0 && d.nodes[e.target].sites.size() >= 2 && !d.nodes[e.target].wedged) wedged_boundary[f] = false;
      }
    if (wedged_boundary[f]) RC_ASSERT(!d.faces[f].orphan);
    if (d.faces[f].orphan) RC_TAG("has an orphan");
  }
  int checked = 0;
  for (int i = 1; i < 16; ++i)
    for (int j = 1; j < 16; ++j) {
      const Point2<Rational> q{Rational(i, 16), Rational(j, 16)};
      const Location loc = locate(d, q);
      if (loc.kind != Location::Kind::face || !wedged_boundary[loc.index]) continue;
      const int v = d.faces[loc.index].site;
      const auto& s = c.input.sites[v];
      for (int k = 1; k < 4; ++k) {
        const Rational t(k, 4);
        const Point2<Rational> p{s.x + t * (q.x - s.x), s.y + t * (q.y - s.y)};
        RC_ASSERT(contains(nearest_sites(c.input, p), v));
        ++checked;
      }
    }
  RC_CLASSIFY(checked > 0, "segments checked");
}

// LS Lemma 6: at a wedged Voronoi vertex owned by v1, v2, v3 (interior, degree 3), the triangle
// v1v2v3 in the counter-clockwise order of the cells around the vertex is positively oriented.
RC_GTEST_PROP(LS_L6, WedgedVertexTrianglesArePositive, ()) {
  const DiagramCase c = *diagram_case();
  RC_TAG(c.kind);
  const Diagram d = diagram_or_discard(c.input);
  for (const DualCell& t : d.dual_triangles) {
    const Node& n = d.nodes[t.vertex];
    if (!n.wedged || !n.boundary_edges.empty() || n.sites.size() != 3) continue;
    const auto& s = c.input.sites;
    RC_ASSERT(anisocert::predicates::orientation(s[t.sites[0]], s[t.sites[1]], s[t.sites[2]]) ==
              anisocert::Sign::positive);
  }
}

// LS Theorem 7: sites include Ω's vertices, every cut arc is owned by the endpoints of the edge
// that cuts it, every arc and vertex wedged ⇒ the dual is a polygonalization of Ω with strictly
// convex cells; the oracle's exact check (BWY §3.2.1, chain argument) must then succeed.
RC_GTEST_PROP(LS_T7, PreconditionsGiveATriangulation, ()) {
  const DiagramCase c = *theorem7_case();
  const Diagram d = diagram_or_discard(c.input);
  RC_TAG(c.kind, d.theorem7.preconditions_hold ? "preconditions hold" : "preconditions fail");
  if (d.theorem7.preconditions_hold) {
    RC_ASSERT(d.dual_check.is_triangulation);
    RC_ASSERT(!d.theorem7.disagreement);
    for (const Face& f : d.faces) RC_ASSERT(!f.orphan);
  }
}
