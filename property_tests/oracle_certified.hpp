#pragma once
// What "certified by the oracle" means for a refiner's finished run (issues 16, 17): the exact D|Ω
// of the mesh's sites has (for LS: no orphans, every arc and vertex wedged, LS Theorem 7's
// preconditions, and) a dual that is a triangulation of Ω and equals the mesh triangle for triangle; and the mesh's
// triangles tile Ω, exactly: each counter-clockwise, every directed edge once, an edge whose
// reverse is no triangle's on ∂Ω, and their areas summing to Ω's (the comparison with the dual
// accepts any three owners of a vertex of degree 4 or more, so it does not see such a polygon
// split twice, left out, or split into overlapping triangles). Returns the exact
// mesh and diagram for the property's own checks, or nothing (tagged) when the oracle refuses the input as
// beyond what it supports (std::domain_error: distances that doubles cannot tell apart).
#include "geometry/mesh.hpp"
#include "geometry/polygon.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"

#include <rapidcheck.h>

#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

namespace anisocert::gen {

// The oracle's D|Ω, or nothing (tagged "the oracle refuses the input") when it refuses it.
inline std::optional<oracle::Diagram> oracle_diagram(const geometry::Mesh<Rational>& m) {
  try {
    return oracle::compute_diagram(m);
  } catch (const std::domain_error& e) {
    RC_TAG("the oracle refuses the input");
    RC_LOG() << e.what() << "\n";
    return std::nullopt;
  }
}

// The exact mesh and its diagram, for the property's own checks.
struct Certified {
  geometry::Mesh<Rational> mesh;
  oracle::Diagram diagram;
};

// The dual part alone, for a refiner that does not promise wedged arcs (BWY: its T is the dual of
// the Voronoi vertices in Ω, a triangulation by BWY §3.2.1, whatever the arcs): the exact D|Ω's
// dual is a triangulation of Ω and equals the mesh, whose triangles tile Ω.
inline std::optional<Certified> assert_exact_dual(const geometry::Mesh<double>& mesh) {
  geometry::Mesh<Rational> m = geometry::exact(mesh);
  std::optional<oracle::Diagram> exact = oracle_diagram(m);
  if (!exact) return std::nullopt;
  const oracle::Diagram& d = *exact;
  RC_ASSERT(d.dual_check.is_triangulation);
  const oracle::MeshDual dual = oracle::compare_with_dual(d, mesh.triangles, 3);
  for (const auto& w : dual.not_dual_witnesses) RC_LOG() << w.why << "\n";
  RC_ASSERT(dual.is_dual());
  std::set<std::pair<int, int>> directed;
  for (const auto& t : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) RC_ASSERT(directed.insert({t[i], t[(i + 1) % 3]}).second);
  const std::size_t n = m.domain.size();
  for (const auto& [a, b] : directed) {
    if (directed.count({b, a})) continue;
    bool on_boundary = false;
    for (std::size_t e = 0; e < n && !on_boundary; ++e)
      on_boundary = geometry::on_segment(m.sites[static_cast<std::size_t>(a)], m.domain[e], m.domain[(e + 1) % n]) &&
                    geometry::on_segment(m.sites[static_cast<std::size_t>(b)], m.domain[e], m.domain[(e + 1) % n]);
    RC_ASSERT(on_boundary);
  }
  Rational twice_area(0), twice_omega(0);
  for (const auto& t : mesh.triangles) {
    const auto &a = m.sites[static_cast<std::size_t>(t[0])], &b = m.sites[static_cast<std::size_t>(t[1])], &c = m.sites[static_cast<std::size_t>(t[2])];
    const Rational o = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    RC_ASSERT(o > 0);
    twice_area += o;
  }
  for (std::size_t k = 0; k < m.domain.size(); ++k) {
    const auto &p = m.domain[k], &q = m.domain[(k + 1) % m.domain.size()];
    twice_omega += p.x * q.y - q.x * p.y;
  }
  RC_ASSERT(twice_area == twice_omega);
  return Certified{std::move(m), std::move(*exact)};
}

// LS's promise (LS Theorem 7): the exact dual above, with no orphans, every arc and vertex wedged
// and Theorem 7's preconditions.
inline std::optional<Certified> assert_dual_of_exact_diagram(const geometry::Mesh<double>& mesh) {
  auto certified = assert_exact_dual(mesh);
  if (!certified) return std::nullopt;
  const oracle::Diagram& d = certified->diagram;
  for (const auto& face : d.faces) RC_ASSERT(!face.orphan);
  for (const auto& n : d.nodes) RC_ASSERT(n.wedged);
  for (const auto& a : d.arcs) RC_ASSERT(a.wedged);
  RC_ASSERT(d.theorem7.preconditions_hold);
  return certified;
}

}  // namespace anisocert::gen
