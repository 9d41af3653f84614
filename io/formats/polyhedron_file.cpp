#include "io/formats/polyhedron_file.hpp"

#include "geometry/builtin_polyhedra.hpp"

#include "io/formats/registry.hpp"
#include "io/formats/text_reader.hpp"

#include <algorithm>

namespace anisocert::io {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                                                 [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

geometry::Polyhedron read_off(const std::string& path) {
  const std::string text = read_whole_file(path);
  TextReader in(text, path, '#');
  in.set_context("OFF header");
  in.expect("OFF");
  const std::int64_t nv = in.integer("the vertex count", 4, 100'000'000), nf = in.integer("the face count", 4, 200'000'000);
  in.integer("the edge count", 0, INT64_MAX);
  geometry::Polyhedron p;
  in.set_context("vertices");
  for (std::int64_t i = 0; i < nv; ++i) {
    Rational x = in.number("x"), y = in.number("y");
    p.vertices.push_back({std::move(x), std::move(y), in.number("z")});
  }
  in.set_context("faces");
  for (std::int64_t i = 0; i < nf; ++i) {
    in.integer("a face's vertex count (triangles only)", 3, 3);
    const int a = static_cast<int>(in.integer("a face's vertex", 0, nv - 1)), b = static_cast<int>(in.integer("a face's vertex", 0, nv - 1)),
              c = static_cast<int>(in.integer("a face's vertex", 0, nv - 1));
    p.facets.push_back({a, b, c});
    const std::string_view rest = in.rest_of_line();  // an optional colour
    (void)rest;
  }
  if (!in.at_end()) in.fail("more than the " + std::to_string(nf) + " faces the header declares");
  return p;
}

}  // namespace

geometry::Polyhedron read_polyhedron_file(const std::string& path) {
  geometry::Polyhedron p;
  if (ends_with(path, ".off")) {
    p = read_off(path);
  } else {
    ReadOptions o;
    o.surface = true;
    MeshFile f = read_mesh_file(path, "", o);
    if (f.dimension != 3) throw InputError(path + ": a 2D mesh: --domain takes a closed surface of triangles in 3D");
    if (f.mesh3.triangles.empty()) throw InputError(path + ": no triangles: --domain takes a closed surface of triangles in 3D");
    p.vertices = std::move(f.mesh3.vertices);
    p.facets = std::move(f.mesh3.triangles);
  }
  // Drop the vertices no facet uses; renumber the rest in order.
  std::vector<int> renumber(p.vertices.size(), -1);
  for (const auto& t : p.facets)
    for (int v : t) renumber[v] = 0;
  std::vector<predicates::Point3<Rational>> used;
  for (std::size_t v = 0; v < p.vertices.size(); ++v)
    if (renumber[v] == 0) renumber[v] = static_cast<int>(used.size()), used.push_back(std::move(p.vertices[v]));
  for (auto& t : p.facets)
    for (int& v : t) v = renumber[v];
  p.vertices = std::move(used);
  return p;
}

bool names_polyhedron(const std::string& domain) {
  if (geometry::builtin_polyhedron(domain)) return true;
  for (const char* ext : {".off", ".mesh", ".meshb", ".msh"})
    if (domain.size() > std::string(ext).size() && domain.ends_with(ext)) return true;
  return false;
}

}  // namespace anisocert::io
