#pragma once
// A vertex set judged by the oracle, for `refine --from`'s post-passes (--coarsen removes vertices,
// --relocate moves them): certified when the dual of the exact D|Ω of the sites is a triangulation
// of Ω and LS Theorem 7 is not contradicted (oracle/diagram, decided exactly), and that dual is then
// the mesh. It lives in cli/ because refiners never include the oracle. The lengths and the unit
// share here are doubles: they choose what to try, never a verdict.
#include "geometry/mesh.hpp"

#include <cstddef>
#include <set>
#include <vector>

namespace anisocert::cli {

struct Trial {
  geometry::Mesh<double> mesh;  // the sites judged; with certified, their dual's triangles
  bool certified = false;
  std::set<int> near_failures;  // sites named by the oracle's failed check (indices into mesh)
};

// m's sites, metrics, domain and segments (its triangles ignored), judged; ++diagrams.
Trial judged(geometry::Mesh<double> m, std::size_t& diagrams);

// |b − a| in a's metric, and in both (the geometric mean of the two).
double length_in(const geometry::Mesh<double>& m, int a, int b, int in);
double mean_length(const geometry::Mesh<double>& m, int a, int b);

// Each vertex's neighbours along the triangles' edges.
std::vector<std::set<int>> neighbours(const geometry::Mesh<double>& m);

// The share of unit edges: both lengths in [1/√2, √2].
bool unit_edge(const geometry::Mesh<double>& m, int a, int b);
double unit_share(const geometry::Mesh<double>& m);

// The mean over edges of (log ℓ)², ℓ an edge's geometric-mean length: 0 for a unit mesh.
double length_energy(const geometry::Mesh<double>& m);

}  // namespace anisocert::cli
