#pragma once
// The exact mesh certifier (`anisocert certify`): is a triangle mesh with per-vertex metrics
//  - valid: a triangulation of Ω (triangulation_check.hpp) in which every constrained segment is
//    a union of edges;
//  - locally uniform (LU §3–§4: the final mesh's 1-neighbourhood of every vertex v is Delaunay
//    for M_v): no site strictly inside the M_v-circumellipse of a triangle incident to v (LU
//    Definition 2.1, the lifted in-circle test); sites exactly on it are ties, reported apart.
//    Together with validity (closed fans) the triangles at v are then exactly v's star;
//  - of a given quality: the radius-edge ratio of every triangle in each of its vertices' metrics
//    at most ρ₀, and the distortion τ(M_a, M_b) of every pair of its vertices at most γ₀;
//  - conforming to its metric (metric_checks.hpp): edge lengths, mean-ratio qualities and angles
//    in the metrics, with optional bounds as verdicts.
// Each check's verdict stands on its own: a triangle one check cannot measure (flat, clockwise) is
// counted as such there, and the other checks still run on the rest.
// Every decision is exact (filtered predicates, rational fall-backs); the worst values reported
// next to the verdicts are double approximations.
#include "oracle/certify/metric_checks.hpp"
#include "oracle/certify/triangulation_check.hpp"
#include "geometry/mesh.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace anisocert::oracle {

using geometry::Mesh;

struct CertifyOptions {
  bool valid = true, uniform = true;
  bool metric = false;  // edge lengths, qualities and angles in the metrics (metric_checks.hpp)
  std::optional<Rational> rho0, gamma0;  // quality thresholds, checked when given
  std::optional<std::pair<Rational, Rational>> length_range;   // verdict: every metric length in it
  std::optional<Rational> min_quality;                          // verdict: every mean ratio >= it
  std::optional<Rational> min_angle;                            // verdict: every angle >= it (degrees, in (0, 90])
  // How many witnesses of each list (and failures of `valid`) are described in full; every one is
  // counted and located whatever this is (witness_list.hpp). all_witnesses: every one.
  std::size_t described_witnesses = default_described_witnesses;
  int threads = 0;  // for the locally uniform check (per triangle); 0: one per core
};

// Every list of witnesses holds at most one per triangle (per edge for lengths), and describes
// only its first options.described_witnesses: memory stays proportional to the mesh however bad it
// is (12 bytes a witness beyond those), and a triangle's search stops at its first witness. The
// verdict counts; it needs no witness described.
struct CertifyReport {
  std::optional<TriangulationCheck> valid;
  std::vector<std::string> segment_failures;            // the first options.described_witnesses
  std::size_t segment_failure_count = 0;                // all of them
  bool uniform_checked = false;
  WitnessList uniform_violations, uniform_ties;
  std::size_t incircle_tests = 0;
  std::size_t unmeasured = 0;                           // flat or clockwise triangles: no circumellipse
  double worst_rho = 0, worst_gamma = 0;                // approximations
  int worst_rho_triangle = -1, worst_rho_vertex = -1, worst_gamma_triangle = -1;
  WitnessList rho_violations, gamma_violations;
  std::optional<LengthReport> lengths;
  std::optional<QualityReport> quality;
  std::optional<AngleReport> angles;

  bool valid_holds() const { return valid && valid->is_triangulation && segment_failure_count == 0; }
  bool holds(const CertifyOptions& o) const {
    return (!o.valid || valid_holds()) && (!o.uniform || uniform_violations.empty()) && rho_violations.empty() &&
           gamma_violations.empty() && (!lengths || lengths->range_violations.empty()) &&
           (!quality || quality->violations.empty()) &&
           (!angles || (angles->violations.empty() && angles->undecided_triangles.empty()));
  }
};

// The metric checks need mesh.metrics (one per site); the others only validity.
CertifyReport certify_mesh(const Mesh<Rational>& mesh, const CertifyOptions& options);

}  // namespace anisocert::oracle
