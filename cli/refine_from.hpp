#pragma once
// `anisocert refine --from MESH` (issue 41): a refiner started from a mesh someone else made, and
// the certificate of what it returns. The sites start as MESH's vertices; Ω is the boundary of its
// triangles, every boundary vertex a corner (geometry::boundary_loop); its declared edges inside
// Ω are interior segments (LS §9's PSLG); the metric is the file's own (P1 over its triangles,
// fields/background.hpp), --metric FILE's, or --field's. A coordinate that is not a double is
// rounded to the nearest one and counted (--exact-sites refuses it instead): the refiners work in
// doubles. The mesh is judged by the certifier before and after, with the same numbers `certify`
// prints, and the output's certificate is the refiner's own claim decided by the oracle: the exact
// dual of D|Ω of its vertices (LS Theorem 7) for bwy and ls, locally uniform (LU) for star.
#include "cli/mesh_input.hpp"
#include "fields/metric_field.hpp"
#include "geometry/mesh.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/registry.hpp"

#include <optional>
#include <string>

namespace anisocert::cli {

// The certifier's measures of a mesh in its vertices' metrics (oracle/certify/metric_checks.hpp).
struct MeshMeasures {
  std::size_t vertices = 0, triangles = 0, edges = 0, unit_edges = 0;
  double smallest_angle = 0;   // degrees, approximate
  double median_quality = 0;   // the middle of the median's enclosure
};

struct StartingMesh {
  std::optional<refiners::common::Domain> domain;
  fields::MetricField field;
  std::string metric_source;  // "its own metrics (P1)", "--metric FILE", "--field NAME"
  std::size_t boundary_vertices = 0, interior_segments = 0, rounded = 0;
  MeshMeasures before;
};

// MESH (and its metric) as a refiner's start. UsageError (exit 2, one line) when the mesh is no
// valid triangulation, its metric is not positive definite at a vertex, its boundary is not one
// simple loop (a hole, a pinch), rounding flattens or flips a triangle, or, with exact_sites, a
// coordinate is not a double.
StartingMesh starting_mesh(const MeshInput& in, bool exact_sites, bool quiet);

struct RefinedCertificate {
  bool holds = false;
  std::string line;  // "exact dual of D|Ω …" or why not
  MeshMeasures after;
};

// The refiner's output judged independently of the refiner: the certifier's measures, and its
// certificate decided by the oracle (LS Theorem 7's dual for a dual_of_diagram refiner, LU's local
// uniformity otherwise).
RefinedCertificate certify_refined(const refiners::RefinerEntry& entry, const geometry::Mesh<double>& m, bool quiet);

// The report's before/after lines.
std::string before_after_text(const StartingMesh& start, const RefinedCertificate& c, std::size_t vertices_in, std::size_t removed);

}  // namespace anisocert::cli
