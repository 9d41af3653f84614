#pragma once
// A mesh as another mesher's file holds it: the one mesh shape (geometry::Mesh: sites, metrics
// when the file carries them, triangles, the file's edges, required edges as constrained
// segments) plus what the formats attach to it — references (Medit, Gmsh physical tags, Triangle
// boundary markers, FreeFem labels), corners and required vertices, holes. The domain is left
// empty: a mesh from elsewhere declares its domain by its boundary edges (see the certifier).
// A tetrahedral mesh (dimension 3, issue 39) is in mesh3 instead, with `mesh` empty but for the
// file's edges and their references.
// Every reader and writer in formats/ takes or gives this; writers refuse a number the format
// cannot hold exactly (a rational with no finite decimal expansion in a text format, a rational
// that is not a double in a binary one).
#include "geometry/mesh.hpp"
#include "geometry/mesh3.hpp"
#include "io/input_error.hpp"
#include "predicates/metric.hpp"

#include <string>
#include <vector>

namespace anisocert::io {

struct MeshFile {
  int dimension = 2;                  // 3: a tetrahedral mesh, in mesh3
  geometry::Mesh<Rational> mesh;
  geometry::Mesh3<Rational> mesh3;
  std::vector<int> tetrahedron_refs;  // per mesh3 tetrahedron (triangle_refs: per mesh3 triangle)
  std::vector<int> vertex_refs;       // per site (0 when the format has none)
  std::vector<int> edge_refs;         // per mesh.edges entry
  std::vector<int> triangle_refs;     // per triangle
  std::vector<int> corners;           // site indices (Medit Corners)
  std::vector<int> required_vertices; // site indices (Medit RequiredVertices)
  std::vector<int> required_edges;    // indices into mesh.edges (Medit RequiredEdges)
  std::vector<int> ridges;            // indices into mesh.edges (Medit Ridges)
  std::vector<predicates::Point2<Rational>> holes;  // a point in each hole (Triangle .poly)
  std::string metric_source;          // where mesh.metrics came from, for reports ("" when none)
};

// A file a writer produces: its path and its bytes.
struct FileText {
  std::string path, content;
};

// For a writer of triangle meshes only: throws InputError naming the format when m is tetrahedral.
void require_triangle_mesh(const MeshFile& m, const std::string& format);

// The constrained segments of a file mesh: its required edges and ridges (each an edge of the file).
void set_constrained_segments(MeshFile& f);

// A metric per site from a separate file (or a field): checks the count against the mesh and
// stores them in f.mesh.metrics. source names the metric's origin in the message.
void attach_metrics(MeshFile& f, std::vector<predicates::Sym2<Rational>> metrics, const std::string& source);
// The same for a tetrahedral mesh's 3×3 metrics, in f.mesh3.metrics.
void attach_metrics(MeshFile& f, std::vector<predicates::Sym3<Rational>> metrics, const std::string& source);

using predicates::positive_definite;
// The metric of a scalar size h > 0: I / h² (MMG, BAMG and Gmsh's isotropic size fields).
predicates::Sym2<Rational> metric_of_size(const Rational& h);
predicates::Sym3<Rational> metric3_of_size(const Rational& h);

// The exact decimal text of q for a text format; throws InputError naming `what` when q has no
// finite decimal expansion.
std::string decimal_text(const Rational& q, const std::string& what);
// The double q is, exactly, for a binary format; throws InputError naming `what` otherwise.
double exact_double(const Rational& q, const std::string& what);

}  // namespace anisocert::io
