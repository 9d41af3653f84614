#pragma once
// The Unstructured Grid Adaptation Working Group's measures of a tetrahedral mesh in its vertex
// metrics, so that users can set anisocert's report beside the benchmark's published tables
// (Ibanez, Barral, Krakos, Loseille, Michal, Park, "First benchmark of the Unstructured Grid
// Adaptation Working Group", Procedia Engineering 203, 2017). Floating point: measured values,
// never verdicts (the exact checks are metric_checks.hpp's).
//  - The edge length interpolated logarithmically between the lengths in the endpoints' metrics:
//    l = (l_a − l_b) / ln(l_a / l_b), and l_a when they are equal; its share in [1/√2, √2].
//  - Omega_h's tetrahedron quality: the mean ratio 12 (3 V_M)^(2/3) / Σ ℓ_M² in the metric of the
//    vertex with the largest determinant (Omega_h's maxdet_metric), negative for a tetrahedron of
//    the other orientation than the mesh's, 1 for the regular tetrahedron in that metric.
#include "oracle/certify/enclosed_mesh.hpp"

#include <array>
#include <utility>
#include <vector>

namespace anisocert::oracle {

struct UgawgMeasures {
  std::size_t edges = 0, unit_edges = 0;      // unit: l in [1/√2, √2]
  double shortest = 0, longest = 0, mean_length = 0;
  std::size_t tetrahedra = 0;
  double least_quality = 0, mean_quality = 0;
  std::size_t least_tetrahedron = 0;
  std::array<std::size_t, 10> quality_bins{};  // [0, 0.1), …, [0.9, 1]; below 0 in the first
  std::size_t unmeasured = 0;                  // edges and tetrahedra whose measure overflowed the doubles
};

// The log-interpolated length of edge ab from its lengths in a's and b's metrics.
double log_interpolated_length(double la, double lb);
// Omega_h's quality of tetrahedron abcd in metric M (doubles).
double omega_h_quality(const std::array<predicates::Point3<double>, 4>& p, const predicates::Sym3<double>& M);

// orientation: +1 or −1, the mesh's (tetrahedralization_check), 0 when unknown (taken as +1).
UgawgMeasures ugawg_measures(const EnclosedMesh3& m, const std::vector<std::pair<int, int>>& edges, int orientation);

}  // namespace anisocert::oracle
