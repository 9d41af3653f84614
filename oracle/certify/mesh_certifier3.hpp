#pragma once
// The exact certifier of a tetrahedral mesh with per-vertex 3×3 metrics (issue 39), the 3D twin of
// mesh_certifier.hpp:
//  - valid: tetrahedralization_check.hpp;
//  - locally uniform (LU §3, in dimension 3): no vertex strictly inside the M_v-circumellipsoid of
//    a tetrahedron incident to v (the lifted in-sphere test in M_v, predicates/insphere.hpp, with
//    the tetrahedron's own orientation); vertices exactly on it are ties, reported apart; one
//    witness per tetrahedron as in 2D (its search stops at the first vertex strictly inside, and
//    records one tie at most), a vertex whose metric equals an earlier one's not asked again;
//  - LU's bounds, when given: the radius-edge ratio (LU Definition 3.10: the M_v-circumradius over the
//    shortest edge in M_v) at most ρ₀ in each vertex's metric, and the distortion γ (LU §2, the
//    3×3 predicates/distortion.hpp) at most γ₀ between the vertices of each tetrahedron, exactly;
//  - LU's sliver measure, with the locally uniform check: the quasi-cosphericity of every two
//    tetrahedra sharing a face (quasi_cosphericity.hpp), measured, and decided exactly at γ₀;
//  - conforming to its metric: edge lengths in both endpoints' metrics, the share in
//    [1/√2, √2] decided exactly, and a range as a verdict; the mean-ratio quality in each vertex's
//    metric, enclosed, and a lower bound as a verdict (metric_checks.hpp, one loop for both
//    dimensions each); the dihedral angles at each edge in each end's metric, the smallest and
//    largest measured, a lower bound as a verdict (metric_angles.cpp's loop); beside them UGAWG's measures (ugawg_measures.hpp), measured in doubles.
// Each check's verdict stands on its own; a flat tetrahedron is counted as unmeasured by the
// locally uniform check. Candidates for an M_v-circumellipsoid come from a grid of the vertices,
// within its bounding box enclosed in interval arithmetic (the centre solved by Cramer's rule,
// the half-widths r·√((M⁻¹)ᵢᵢ)); when the enclosure fails (a nearly flat tetrahedron), every
// vertex is a candidate. Each decision is the exact in-sphere sign, interval first.
// Threads: the search per tetrahedron and the sliver measure per face pair on every thread, the
// other checks beside them on a thread of their own; findings are added in order, so the report
// does not depend on the number of threads.
#include "geometry/mesh3.hpp"
#include "oracle/certify/metric_checks.hpp"
#include "oracle/certify/quasi_cosphericity.hpp"
#include "oracle/certify/tetrahedralization_check.hpp"
#include "oracle/certify/ugawg_measures.hpp"

#include <optional>

namespace anisocert::oracle {

struct Certify3Options {
  bool valid = true, uniform = true;
  bool metric = false;                                        // edge lengths in the metrics
  std::optional<std::pair<Rational, Rational>> length_range;  // verdict: every metric length in it
  std::optional<Rational> min_quality;                        // verdict: every mean ratio at least it (in [0, 1])
  std::optional<Rational> min_angle;                          // verdict: every dihedral angle at least it (degrees, (0, 90])
  std::optional<Rational> rho0, gamma0;                       // LU's bounds: radius-edge ratio, distortion (with metrics)
  std::size_t described_witnesses = default_described_witnesses;
  int threads = 0;  // for the locally uniform check and the sliver measure; 0: one per core (the same report)
};

struct Certify3Report {
  std::optional<TetrahedralizationCheck> valid;
  bool uniform_checked = false;
  WitnessList uniform_violations, uniform_ties;  // vertex v, tetrahedron, the vertex inside (or on) the M_v-sphere
  std::size_t insphere_tests = 0, unmeasured = 0;
  std::optional<LengthReport> lengths;
  std::optional<QualityReport> quality;
  double worst_rho = 0, worst_gamma = 0;  // approximations
  int worst_rho_tetrahedron = -1, worst_rho_vertex = -1, worst_gamma_tetrahedron = -1;
  WitnessList rho_violations, gamma_violations;  // one per tetrahedron each
  std::optional<CosphericityReport> cosphericity;  // with the uniform check: LU's sliver measure
  std::optional<AngleReport> angles;    // dihedral angles in each edge end's metric
  std::optional<UgawgMeasures> ugawg;  // with the metric checks: UGAWG's measures, floating point
  std::size_t tetrahedra = 0;

  bool valid_holds() const { return valid && valid->valid; }
  bool holds(const Certify3Options& o) const {
    return (!o.valid || valid_holds()) && (!o.uniform || uniform_violations.empty()) && rho_violations.empty() && gamma_violations.empty() && (!lengths || lengths->range_violations.empty()) &&
           (!quality || quality->violations.empty()) &&
           (!angles || (angles->violations.empty() && angles->undecided_triangles.empty()));
  }
};

// The uniform and metric checks need mesh.metrics (one per vertex).
Certify3Report certify_mesh3(const geometry::Mesh3<Rational>& mesh, const Certify3Options& options);

}  // namespace anisocert::oracle
