#pragma once
// What "certified by the oracle" means for a refiner's finished run (issue 16): the exact D|Ω of
// the mesh's sites has no orphans, every arc and vertex wedged, LS Theorem 7's preconditions, and
// a dual that is a triangulation of Ω and equals the mesh triangle for triangle. Returns the exact
// mesh and diagram for the property's own checks, or nothing (tagged) when the oracle refuses the input as
// beyond what it supports (std::domain_error: distances that doubles cannot tell apart).
#include "geometry/mesh.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"

#include <rapidcheck.h>

#include <optional>
#include <stdexcept>

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

inline std::optional<Certified> assert_dual_of_exact_diagram(const geometry::Mesh<double>& mesh) {
  geometry::Mesh<Rational> m = geometry::exact(mesh);
  std::optional<oracle::Diagram> exact = oracle_diagram(m);
  if (!exact) return std::nullopt;
  const oracle::Diagram& d = *exact;
  for (const auto& face : d.faces) RC_ASSERT(!face.orphan);
  for (const auto& n : d.nodes) RC_ASSERT(n.wedged);
  for (const auto& a : d.arcs) RC_ASSERT(a.wedged);
  RC_ASSERT(d.theorem7.preconditions_hold);
  RC_ASSERT(d.dual_check.is_triangulation);
  const oracle::MeshDual dual = oracle::compare_with_dual(d, mesh.triangles, 3);
  for (const auto& w : dual.not_dual_witnesses) RC_LOG() << w.why << "\n";
  RC_ASSERT(dual.is_dual());
  return Certified{std::move(m), std::move(*exact)};
}

}  // namespace anisocert::gen
