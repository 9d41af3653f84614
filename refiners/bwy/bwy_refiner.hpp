#pragma once
// Boissonnat, Wormser & Yvinec's variant of Labelle–Shewchuk Voronoi refinement (BWY §3.2.2) on a
// domain Ω and a metric field: the sites start as Ω's corners (and points); the refiner keeps the
// Voronoi vertices of the true anisotropic diagram in closed Ω and the set T of their dual
// triangles, and applies rules.hpp's rules in priority order until none applies. The output is T,
// which BWY §3.2.1 proves a triangulation of Ω once no rule applies; the run checks that local
// embedding itself (every site a vertex of T, every boundary subsegment in one triangle, every
// other edge in two on opposite sides) and says which part fails, if one does.
//
// The Voronoi vertices come from the refiners' vertex machinery (common/vertex_subdivision.hpp:
// certified boxes of the points where three distances d_p(x)² are equal and no other is smaller).
// BWY Lemma 1 computes the same points as the 3-faces of the power diagram of the lifted spheres
// σ(p) in R⁵ met by the manifold x̂ = (x, x²ᵣₛ): power(x̂, σ_p) = ‖x̂‖² + d_p(x)², so on the manifold
// the power diagram's order is the distances' order. The tests check that the two agree at every
// vertex (property_tests/bwy_lifting_properties.cpp); docs/refiners.md says why the refiner does not lift.
// The refiners never include the oracle (DESIGN.md § Layers); the tests certify every finished
// run with it.
#include "fields/metric_field.hpp"
#include "refiners/bwy/parameters.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/refinement_loop.hpp"

#include <string>

namespace anisocert::refiners::bwy {

struct BwyResult : common::RefineResult {
  // What a stopped run leaves (not counted when the time budget stopped it): subsegments still
  // encroached or no edge of T, and Voronoi vertices of T to which rule 3, 4, 5 or 6 applies.
  std::size_t encroached_left = 0, unedged_left = 0, violators_left = 0;
  // Voronoi vertices of T left badly shaped by rule 3's exemption at sharp corners (counted with the rest).
  std::size_t exempt_left = 0;
  bool left_counted = true;
  // Why T is not a local embedding (BWY §3.2.1) at the end; empty when it is (or not counted).
  std::string embedding_failure;
  // With off-centres: how often rule 4 or 5 took another vertex it allows than the one it fired at.
  std::size_t other_vertex_choices = 0;
};

// Throws common::FieldError when the field's metric is not finite and positive definite at a site.
BwyResult refine_bwy(const common::Domain& domain, const fields::MetricField& field, const BwyParameters& p,
                     const common::Progress& progress = {});

}  // namespace anisocert::refiners::bwy
