#pragma once
// `refine --from MESH --coarsen` (issue 41): vertices removed from a refiner's output where that
// brings its edges nearer unit length, each removal kept only when the oracle certifies the rest:
// the dual of the exact D|Ω of the remaining vertices is a triangulation of Ω with every segment an
// edge (LS Theorem 7's conclusion, decided exactly; dual_trial.hpp), and that dual is the new mesh.
//
// Where to remove is a choice in doubles (it never makes a verdict): an interior vertex (on no
// segment) with an edge shorter than 1/√2 and none longer than √2 in the geometric mean of its
// ends' lengths, shortest first; the removals of a round have disjoint closed neighbourhoods
// (DisjointNeighbourhoods, dual_trial.hpp). A round removes such a set; the oracle then judges the
// remaining vertices: the removals next to the cells its check names are put back, and the rest
// tried again; a round whose certified mesh has no larger share
// of unit edges (both lengths in [1/√2, √2], in doubles) tries the better half. A vertex put back
// three times is not tried again, so coarsening ends; it ends when a round removes nothing and no
// vertex is left to try. Only a dual_of_diagram refiner's output is coarsened (its certificate is
// the dual; a star refiner's, local uniformity, would need the stars rebuilt).
//
// With `--collapse` a removal is an edge collapse: the vertex's nearest neighbour (the other end of
// its shortest edge), when it is on no segment and the closed neighbourhoods of both ends meet no
// other change's, moves to the midpoint of their edge and takes the field's metric there, in the
// same trial (otherwise the removal is a plain one, when v's own neighbourhood is free); a
// failure next to either end puts the collapse back. The dual after a removal near BWY's
// rule 4 and 5 sites is often no triangulation; with the neighbour moved into the gap it often is.
#include "fields/metric_field.hpp"
#include "geometry/mesh.hpp"

#include <cstddef>

namespace anisocert::cli {

struct Coarsened {
  geometry::Mesh<double> mesh;
  std::size_t removed = 0, collapsed = 0, diagrams = 0;  // collapsed: the removals that moved a neighbour
};

// m: a finished run's mesh, the exact dual of D|Ω of its sites (sites, metrics, domain, segments).
// collapse: each removal is an edge collapse when it can be (above); field: the metric a moved
// vertex takes at its new place.
Coarsened coarsen(const geometry::Mesh<double>& m, const fields::MetricField& field, bool collapse, bool quiet);

}  // namespace anisocert::cli
