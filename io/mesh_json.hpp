#pragma once
// The project's own file of sites, metrics, domain, segments and triangles (DESIGN.md § Command line
// and files), read into and written from the one mesh shape, geometry::Mesh:
//   {"sites": [{"x": X, "y": Y, "metric": [m11, m12, m22]}, ...],   required, non-empty
//    "domain": [[X, Y], ...],                                        optional, >= 3 vertices
//    "segments": [[i, j], ...],                                      optional
//    "edges": [[i, j], ...],                                         optional (a mesh's declared edges)
//    "triangles": [[i, j, k], ...]}                                  optional (a mesh)
// A number is a JSON string (integer, fraction or decimal, see parse_rational) or a plain JSON
// number, both taken exactly from their text (0.1 is 1/10). Checked exactly: every metric is
// positive definite; the domain is a simple counter-clockwise polygon (consecutive collinear
// vertices allowed when the boundary runs straight on); no two sites coincide; every site lies
// in the closed domain; segments join two distinct existing sites and none repeats; triangles
// name three distinct existing sites (whether they form a mesh is the certifier's verdict).
// Without "domain", a mesh (with "triangles") has no domain polygon: its domain is the union of its
// triangles, bounded by its "edges" when there are any (geometry::Mesh::edges); a site set's is
// the sites' bounding box enlarged on every side by max(width, height)/8 (by 1 when both are 0),
// counter-clockwise from the lower left corner.
#include "geometry/mesh.hpp"
#include "io/input_error.hpp"

#include <istream>
#include <optional>
#include <string>

namespace anisocert::io {

// Throws InputError; source_name is the file name used in messages.
geometry::Mesh<Rational> read_mesh_json(std::istream& in, const std::string& source_name);
// The file at path (a file that cannot be opened is an InputError too).
geometry::Mesh<Rational> read_mesh_json_file(const std::string& path);
// The same, for a mesh: "triangles" must be present and non-empty.
geometry::Mesh<Rational> read_triangle_mesh_file(const std::string& path);
// A refiner's domain: the "domain" polygon of a file in this format ("sites" may be absent), with
// the rest of a PSLG in two optional keys of its own:
//    "points": [[X, Y], ...]                    vertices inside Ω
//    "interior_segments": [[i, j], ...]         segments between vertices: i < n a corner, else
//                                               point i − n (n corners)
// Read and indexed here; their geometry against Ω is the refiners' to check (refiners/common/domain).
struct DomainFile {
  geometry::Polygon<Rational> corners;
  std::vector<predicates::Point2<Rational>> points;
  std::vector<std::pair<int, int>> interior_segments;
};
DomainFile read_domain_file(const std::string& path);

// Two sites at one point (the first such pair by (x, y), lower indices first), if any: the diagram
// needs distinct sites (docs/oracle.md).
std::optional<std::pair<std::size_t, std::size_t>> coincident_sites(const std::vector<predicates::Point2<Rational>>& sites);

// The file of a mesh, every number written as its exact text (a decimal expansion, or a fraction),
// so that `anisocert certify` reads exactly the numbers written (a refiner's doubles included).
// Throws InputError when a site has no metric.
std::string mesh_json(const geometry::Mesh<Rational>& m);

}  // namespace anisocert::io
