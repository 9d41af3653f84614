#pragma once
// LU's sliver measure on a tetrahedral mesh (issue 39): the quasi-cosphericity (LU Definitions
// 3.6 and 3.9) of the five vertices of every two tetrahedra that share a face, in the metric of
// each of the five (LU Lemma 3.8 takes the metric of a vertex of the configuration).
//  - measured, in doubles: the critical distortion γ* of each configuration, the least γ₀ for
//    which it is γ₀-cospherical (predicates/quasi_cospherical.hpp: (Σ h⁺ / Σ |h⁻|)^(1/4) over the
//    eigenvalues of G·M), the least over the five metrics; 1 exactly when the five are cospherical
//    in one of the metrics (decided exactly: the in-sphere sign is 0);
//  - with γ₀ (LU's distortion bound, `--gamma0`): how many configurations are γ₀-cospherical,
//    decided exactly (intervals, then rationals), how many lie exactly at the boundary, and for
//    those cospherical LU Definition 3.9's radius-edge ratio (the least M-circumradius of the
//    five's four-point subsets over their shortest M-distance, in doubles): the quantity LU's
//    Pick_valid keeps away from small values. One witness per configuration.
// A measure, not a verdict: LU's Theorem 4.5 bounds radius-edge ratios and distortion, and a mesh
// it certifies may still hold γ₀-cospherical configurations (every grid does).
#include "oracle/certify/enclosed_mesh.hpp"
#include "oracle/certify/witness_list.hpp"

#include <limits>
#include <optional>

namespace anisocert::oracle {

struct CosphericityReport {
  std::size_t configurations = 0;   // pairs of non-flat tetrahedra sharing a face
  std::size_t unmeasured = 0;       // γ* beyond the doubles (overflow)
  std::size_t cospherical = 0;      // exactly cospherical in a vertex's metric (γ* = 1)
  double least_critical = std::numeric_limits<double>::infinity();  // approximate γ*
  int least_tetrahedra[2] = {-1, -1};
  // With γ₀:
  bool decided = false;
  std::size_t quasi_cospherical = 0;  // exact: γ₀-cospherical in some vertex's metric
  std::size_t at_boundary = 0;        // exact: at γ₀ exactly in some vertex's metric, strictly in none
  double least_radius_edge = std::numeric_limits<double>::infinity();  // Definition 3.9, approximate
  int least_radius_edge_tetrahedra[2] = {-1, -1};
  WitnessList witnesses;  // vertex (the metric), tetrahedron, the other tetrahedron
};

// On `threads` threads (0: one per core); the report does not depend on their number.
CosphericityReport check_quasi_cosphericity(const EnclosedMesh3& m, const std::optional<Rational>& gamma0,
                                            std::size_t described = all_witnesses, int threads = 1);

}  // namespace anisocert::oracle
