#pragma once
// `refine --from MESH --relocate` (issue 41): interior vertices of a refiner's output moved toward
// unit edges, each move kept only when the oracle certifies the moved sites: the dual of the exact
// D|Ω of the sites is a triangulation of Ω (LS Theorem 7's conclusion, decided exactly;
// dual_trial.hpp), and that dual is the new mesh. A moved site takes the field's metric at its new
// place. No vertex is added or removed, so the sites keep their indices.
//
// Where to move is a choice in doubles (it never makes a verdict). Each neighbour w of v proposes
// the point at unit length from w toward v (w + (v − w)/ℓ, ℓ the geometric mean of the edge's
// lengths in its ends' metrics, the rest length of DistMesh's springs). v may go the whole way to
// the proposals' mean, half or a quarter of it, each step taken only when it lands strictly inside
// one of v's triangles (so v stays inside Ω and off every other site); the step kept is the one
// that makes v's own edges best: more of them unit (both lengths in [1/√2, √2]), or as many and
// Σ (log ℓ)² lower by a tenth. A vertex with such a step is a candidate; the vertices moved at once
// have disjoint closed neighbourhoods (DisjointNeighbourhoods, dual_trial.hpp), best gain first
// (unit edges gained, then Σ (log ℓ)² lost). The oracle then judges
// the moved set (keep_certified, dual_trial.hpp): the moves next to what its check names are
// undone and the rest tried again; a certified mesh with a smaller share of unit edges, or the
// same share and no lower mean (log ℓ)², tries the better half. A vertex undone three times is not
// tried again, a round that keeps nothing counts one undoing of each vertex it tried, and at most
// `rounds` rounds run, so relocating ends.
#include "fields/metric_field.hpp"
#include "geometry/mesh.hpp"

#include <cstddef>

namespace anisocert::cli {

struct Relocated {
  geometry::Mesh<double> mesh;
  std::size_t moves = 0, diagrams = 0;
};

// m: a finished run's mesh, the exact dual of D|Ω of its sites; field: the metric of a moved site.
Relocated relocate(const geometry::Mesh<double>& m, const fields::MetricField& field, bool quiet, int rounds = 20);

}  // namespace anisocert::cli
