// The refiners' true diagram (refiners/common/vertex_subdivision.hpp) against the exact oracle
// and against itself.
//
// Sites on the 1/128 grid of the unit square with metrics from a smooth random field
// (generators/fields.hpp), so that bisectors are ellipses, hyperbolas and parabolas, and cells have
// islands and orphans.
// - VerticesAreTheExactDiagramsOrphansIncluded: inserted one by one, the vertices in Ω = [0, 1]²
//   are the oracle's Voronoi vertices of D|Ω, as site triples with their counts (a triple can have
//   two vertices), and each exact vertex lies in its box.
// - WithOmegaTheVerticesInOmegaAreTheExactDiagrams: with Ω an L given to the subdivision, the
//   vertices of D|Ω are all kept, and those kept inside Ω are the oracle's.
// - TheOrderOfInsertionChangesNothing: the same sites in another order give the same vertices.
#include "geometry/mesh.hpp"
#include "oracle/diagram/diagram.hpp"
#include "property_tests/generators/fields.hpp"
#include "property_tests/oracle_certified.hpp"
#include "refiners/common/vertex_subdivision.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace anisocert;
using refiners::common::MetricSite;
using refiners::common::VertexSubdivision;

namespace {

// in_L: only points of the L [0, 1]² without the open quarter x > ½, y > ½.
std::vector<MetricSite> random_sites(const gen::SmoothField& f, int most, bool in_L = false) {
  const int n = *rc::gen::inRange(3, most + 1);
  std::set<std::pair<int, int>> used;
  std::vector<MetricSite> sites;
  while (static_cast<int>(sites.size()) < n) {
    int i = *rc::gen::inRange(0, 129), j = *rc::gen::inRange(0, 129);
    while (!used.insert({i, j}).second) i = (i + 1) % 129, j = i == 0 ? (j + 1) % 129 : j;  // small sizes repeat
    if (in_L && i > 64 && j > 64) continue;
    sites.push_back({{i / 128.0, j / 128.0}, f.at(i / 128.0, j / 128.0)});
  }
  return sites;
}

// The live vertices, as increasing site triples, with how many each triple has.
std::map<std::array<int, 3>, int> triples(const VertexSubdivision& s, const std::vector<int>& rename = {}) {
  std::map<std::array<int, 3>, int> out;
  for (const auto& v : s.vertices()) {
    if (v.holders == 0) continue;
    std::array<int, 3> t = v.sites;
    if (!rename.empty())
      for (int& k : t) k = rename[static_cast<std::size_t>(k)];
    std::sort(t.begin(), t.end());
    ++out[t];
  }
  return out;
}

constexpr refiners::common::Box unit{0, 1, 0, 1};

// The sites as an exact mesh on the domain with these corners, for the oracle.
geometry::Mesh<Rational> exact_mesh(const std::vector<MetricSite>& sites, const std::vector<predicates::Point2<double>>& corners) {
  geometry::Mesh<Rational> m;
  for (const auto& site : sites) {
    m.sites.push_back({Rational(site.p.x), Rational(site.p.y)});
    m.metrics.push_back({Rational(site.M.m11), Rational(site.M.m12), Rational(site.M.m22)});
  }
  for (const auto& c : corners) m.domain.push_back({Rational(c.x), Rational(c.y)});
  return m;
}

// The oracle's Voronoi vertices of D|Ω as increasing site triples with their counts, asserting
// each of degree 3 (more would have left a leaf unresolved) and held by a live vertex of s with
// its triple: the oracle's point, rounded to its grid, is within a grid step of the box.
std::map<std::array<int, 3>, int> exact_vertices_held(const oracle::Diagram& d, const VertexSubdivision& s) {
  std::map<std::array<int, 3>, int> exact;
  for (const auto& n : d.nodes) {
    if (n.kind != oracle::Node::Kind::voronoi) continue;
    RC_ASSERT(n.sites.size() == 3u);
    ++exact[{n.sites[0], n.sites[1], n.sites[2]}];
    const auto [x, y] = d.original_xy(n.at);
    bool held = false;
    for (const auto& v : s.vertices())
      if (v.holders > 0 && v.sites == std::array<int, 3>{n.sites[0], n.sites[1], n.sites[2]})
        held = held || (x >= v.box.box.x.lo - d.grid && x <= v.box.box.x.hi + d.grid && y >= v.box.box.y.lo - d.grid &&
                        y <= v.box.box.y.hi + d.grid);
    RC_ASSERT(held);
  }
  return exact;
}

}  // namespace

RC_GTEST_PROP(RefinerVertexSubdivision, VerticesAreTheExactDiagramsOrphansIncluded, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  const std::vector<MetricSite> sites = random_sites(f, 12);
  VertexSubdivision s(unit, 0x1p-40);
  for (const auto& site : sites) s.insert(site);
  RC_PRE(s.unresolved().empty());

  const auto exact_diagram = gen::oracle_diagram(exact_mesh(sites, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  if (!exact_diagram) return;
  const oracle::Diagram& d = *exact_diagram;
  RC_TAG(std::any_of(d.faces.begin(), d.faces.end(), [](const auto& face) { return face.orphan; }) ? "D|Ω has orphans" : "no orphans");
  const std::map<std::array<int, 3>, int> exact = exact_vertices_held(d, s);
  std::size_t count = 0;
  for (const auto& [t, k] : exact) count += static_cast<std::size_t>(k);
  RC_TAG(count == 0 ? "no vertex in Ω" : count < 5 ? "1–4 vertices" : "5 or more vertices");
  RC_ASSERT(triples(s) == exact);
}

// With Ω given (omega, an L inside R), the subdivision keeps D's vertices in and near Ω only:
// every Voronoi vertex of the oracle's D|Ω is among its live vertices (triple and place), and every
// live vertex whose box lies inside closed Ω (decided exactly) is one of the oracle's, triple for
// triple and no more of them. Sites in the L.
RC_GTEST_PROP(RefinerVertexSubdivision, WithOmegaTheVerticesInOmegaAreTheExactDiagrams, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  const std::vector<MetricSite> sites = random_sites(f, 12, true);
  const refiners::common::Domain L({{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}});
  VertexSubdivision s(unit, 0x1p-40, &L);
  for (const auto& site : sites) s.insert(site);
  RC_PRE(s.unresolved().empty());
  const auto exact_diagram = gen::oracle_diagram(exact_mesh(sites, L.corners()));
  if (!exact_diagram) return;
  const std::map<std::array<int, 3>, int> exact = exact_vertices_held(*exact_diagram, s);
  std::map<std::array<int, 3>, int> inside;
  std::size_t near = 0;
  for (const auto& v : s.vertices()) {
    if (v.holders == 0) continue;
    const refiners::common::Box b{v.box.box.x.lo, v.box.box.x.hi, v.box.box.y.lo, v.box.box.y.hi};
    if (L.contains(b) == std::optional<bool>(true)) ++inside[v.sites];
    else ++near;
  }
  for (const auto& [t, k] : inside) RC_ASSERT(exact.count(t) && k <= exact.at(t));
  RC_TAG(exact.empty() ? "no vertex in Ω" : "vertices in Ω", near == 0 ? "none kept outside" : "some kept near Ω");
}

RC_GTEST_PROP(RefinerVertexSubdivision, TheOrderOfInsertionChangesNothing, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  const std::vector<MetricSite> sites = random_sites(f, 20);
  std::vector<int> order(sites.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::reverse(order.begin(), order.end());
  std::rotate(order.begin(), order.begin() + *rc::gen::inRange<std::size_t>(0, order.size()), order.end());
  VertexSubdivision one(unit, 0x1p-40), other(unit, 0x1p-40);
  for (const auto& site : sites) one.insert(site);
  for (int k : order) other.insert(sites[static_cast<std::size_t>(k)]);
  RC_PRE(one.unresolved().empty() && other.unresolved().empty());
  RC_ASSERT(triples(one) == triples(other, order));
}
