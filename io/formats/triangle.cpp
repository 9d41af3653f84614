// Shewchuk's Triangle files as its pages define them: https://www.cs.cmu.edu/~quake/triangle.node.html,
// triangle.ele.html and triangle.poly.html. Choices where the pages leave room:
// - every list of the three files (vertices, triangles, segments, holes, regions) is numbered
//   consecutively from the base the first vertex sets (0 or 1), as Triangle writes them;
// - 6-node triangles (Triangle's -o2) are refused: the certifier takes linear triangles, and the
//   midpoint vertices would be sites of no triangle;
// - a triangle's reference is its first attribute when that is an integer (a region number, as
//   Triangle's -A propagates it), 0 otherwise; vertex attributes are read and not kept;
// - the .poly's own vertex list is empty ("0 2 0 1", as Triangle writes it) or repeats the .node's
//   vertices (same count, same coordinates): the .ele's indices refer to the .node;
// - the .poly's regional attributes are read ("<region #> <x> <y> <attribute> <maximum area>")
//   and not kept.
#include "io/formats/triangle.hpp"

#include "io/formats/text_reader.hpp"
#include "numbers/excerpt.hpp"

#include <climits>
#include <filesystem>

namespace anisocert::io {
namespace {
namespace triangle_files {

using predicates::Point2;

// Entry numbers. triangle.node.html: "Vertices must be numbered consecutively, starting from one
// or zero". The first vertex fixes the base; every list of the files counts from it.
class Numbering {
 public:
  // Reads the number of entry i (from 0) of a list of `kind`s; the entry's name as the file numbers
  // it ("vertex 1"), for the messages about its fields.
  std::string entry(TextReader& r, const std::string& kind, std::int64_t i) {
    const std::string expected = base_ < 0 ? kind + " 0 or 1" : kind + " " + std::to_string(base_ + i);
    const std::int64_t k = r.integer("the number of " + expected, INT64_MIN, INT64_MAX);
    if (base_ < 0 && (k == 0 || k == 1)) base_ = static_cast<int>(k);
    if (base_ < 0 || k != base_ + i)
      r.fail(kind + " " + std::to_string(k) + ": expected " + expected +
             " (Triangle numbers entries consecutively from 0 or 1, as the first vertex)");
    return kind + " " + std::to_string(k);
  }

  // A vertex number of the files, among n vertices, as a site index.
  int vertex(TextReader& r, const std::string& what, std::int64_t n) const {
    const std::int64_t lo = base_ < 0 ? 0 : base_;
    const std::int64_t k = r.integer(what, INT64_MIN, INT64_MAX);
    if (k < lo || k - lo >= n)
      r.fail(what + " " + std::to_string(k) + " is out of range (" + std::to_string(n) + " vertices numbered from " +
             std::to_string(lo) + ")");
    return static_cast<int>(k - lo);
  }

 private:
  int base_ = -1;  // unknown before the first vertex
};

struct Vertices {
  std::vector<Point2<Rational>> sites;
  std::vector<int> markers;  // 0 without a marker column
};

int read_marker(TextReader& r, const std::string& what) {
  return static_cast<int>(r.integer(what + ": boundary marker", INT_MIN, INT_MAX));
}

// count attributes (reals, "copied unchanged to the output mesh"); the first, or 0 without any.
Rational read_attributes(TextReader& r, const std::string& what, std::int64_t count) {
  Rational first = 0;
  for (std::int64_t k = 0; k < count; ++k) {
    Rational a = r.number(what + ": attribute");
    if (k == 0) first = std::move(a);
  }
  return first;
}

// An integral first attribute is the triangle's reference (see the top of the file).
int reference_of(const Rational& attribute) {
  if (denominator(attribute) != 1 || attribute < INT_MIN || attribute > INT_MAX) return 0;
  return numerator(attribute).convert_to<int>();
}

// A header count: a non-negative int.
std::int64_t read_count(TextReader& r, const std::string& what) { return r.integer(what, 0, INT_MAX); }

// Nothing but blanks and comments after the declared entries.
void expect_end(TextReader& r, const std::string& section, std::int64_t declared) {
  if (!r.at_end())
    r.fail(section + ": more data than the header declares (" + std::to_string(declared) + "): " +
           quoted_excerpt(r.peek()));
}

// triangle.node.html (and the first section of a .poly): "<# of vertices> <dimension (must be 2)>
// <# of attributes> <# of boundary markers (0 or 1)>", then "<vertex #> <x> <y> [attributes]
// [boundary marker]".
Vertices read_vertices(TextReader& r, Numbering& numbering) {
  const std::int64_t n = read_count(r, "vertex header: number of vertices");
  const std::int64_t dimension = r.integer("vertex header: dimension", INT64_MIN, INT64_MAX);
  if (dimension != 2)
    r.fail("vertex header: dimension " + std::to_string(dimension) + ": Triangle's files are planar (dimension 2)");
  const std::int64_t attributes = read_count(r, "vertex header: number of attributes");
  const bool marked = r.integer("vertex header: number of boundary markers", 0, 1) == 1;
  Vertices v;
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "vertex", i);
    v.sites.push_back({r.number(what + ": x"), r.number(what + ": y")});
    read_attributes(r, what, attributes);
    v.markers.push_back(marked ? read_marker(r, what) : 0);
  }
  return v;
}

// triangle.ele.html: "<# of triangles> <nodes per triangle> <# of attributes>", then
// "<triangle #> <node> <node> <node> ... [attributes]", corners counterclockwise.
void read_triangles(TextReader& r, Numbering& numbering, std::int64_t nv, MeshFile& f) {
  const std::int64_t n = read_count(r, "triangle header: number of triangles");
  const std::int64_t nodes = r.integer("triangle header: nodes per triangle", INT64_MIN, INT64_MAX);
  if (nodes == 6)
    r.fail("triangle header: 6 nodes per triangle (Triangle's -o2 quadratic triangles) are not read: anisocert "
           "certifies linear triangles");
  if (nodes != 3) r.fail("triangle header: " + std::to_string(nodes) + " nodes per triangle, where Triangle writes 3");
  const std::int64_t attributes = read_count(r, "triangle header: number of attributes");
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "triangle", i);
    std::array<int, 3> t{};
    for (int& corner : t) corner = numbering.vertex(r, what + ": corner", nv);
    f.mesh.triangles.push_back(t);
    f.triangle_refs.push_back(reference_of(read_attributes(r, what, attributes)));
  }
  expect_end(r, "triangles", n);
}

bool same_sites(const std::vector<Point2<Rational>>& a, const std::vector<Point2<Rational>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  return true;
}

// triangle.poly.html: "<# of segments> <# of boundary markers (0 or 1)>", then "<segment #>
// <endpoint> <endpoint> [boundary marker]". Triangle keeps every segment as a union of edges, so
// each is a declared edge and a constrained segment.
void read_segments(TextReader& r, Numbering& numbering, std::int64_t nv, MeshFile& f) {
  const std::int64_t n = read_count(r, "segment header: number of segments");
  const bool marked = r.integer("segment header: number of boundary markers", 0, 1) == 1;
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "segment", i);
    const int a = numbering.vertex(r, what + ": endpoint", nv);
    const int b = numbering.vertex(r, what + ": endpoint", nv);
    f.mesh.edges.emplace_back(a, b);
    f.mesh.segments.emplace_back(a, b);
    f.edge_refs.push_back(marked ? read_marker(r, what) : 0);
  }
}

// triangle.poly.html: "<# of holes>", then "<hole #> <x> <y>".
void read_holes(TextReader& r, Numbering& numbering, MeshFile& f) {
  const std::int64_t n = read_count(r, "hole header: number of holes");
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "hole", i);
    f.holes.push_back({r.number(what + ": x"), r.number(what + ": y")});
  }
}

// triangle.poly.html, optional: "<# of regional attributes and/or area constraints>", then
// "<region #> <x> <y> <attribute> <maximum area>"; read, not kept. Returns the declared count.
std::int64_t skip_regions(TextReader& r, Numbering& numbering) {
  const std::int64_t n = read_count(r, "region header: number of regions");
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "region", i);
    for (const char* field : {": x", ": y", ": attribute", ": maximum area"}) r.number(what + field);
  }
  return n;
}

// triangle.poly.html: vertices (see the top of the file), segments, holes, regions (optional).
void read_poly(TextReader& r, Numbering& numbering, const Vertices& node, MeshFile& f) {
  const Vertices own = read_vertices(r, numbering);
  if (!own.sites.empty() && !same_sites(own.sites, node.sites))
    r.fail("vertices: the .poly lists " + std::to_string(own.sites.size()) +
           " vertices that are not the .node's (a .poly beside a .node lists none, \"0 2 0 1\", or the same)");
  const auto nv = static_cast<std::int64_t>(node.sites.size());
  read_segments(r, numbering, nv, f);
  read_holes(r, numbering, f);
  if (!r.at_end()) expect_end(r, "regions", skip_regions(r, numbering));
}

// BASE of BASE.node, BASE.ele or BASE.poly (any other path is its own BASE).
std::string base_of(const std::string& path) {
  const std::filesystem::path p(path);
  const std::string e = p.extension().string();
  return e == ".node" || e == ".ele" || e == ".poly" ? std::filesystem::path(p).replace_extension().string() : path;
}

// A file the mesh cannot be read without, named with the path the user gave.
std::string required_file(const std::string& given, const std::string& file) {
  if (!std::filesystem::exists(file))
    throw InputError(given + ": the Triangle mesh needs " + file + ", which does not exist");
  return read_whole_file(file);
}

// A reference of a writer's list: 0 when the mesh has none (MeshFile: "0 when the format has none").
int ref_of(const std::vector<int>& refs, std::size_t i) { return i < refs.size() ? refs[i] : 0; }

std::string point_text(const Point2<Rational>& p, const std::string& what) {
  return decimal_text(p.x, what + ": x") + " " + decimal_text(p.y, what + ": y");
}

// Written numbered from 1, Triangle's default (-z numbers from 0), with a boundary marker column.
std::string node_text(const MeshFile& m, const std::string& source) {
  const auto& sites = m.mesh.sites;
  std::string s = std::to_string(sites.size()) + " 2 0 1\n";
  for (std::size_t i = 0; i < sites.size(); ++i)
    s += std::to_string(i + 1) + " " + point_text(sites[i], source + ": vertex " + std::to_string(i + 1)) + " " +
         std::to_string(ref_of(m.vertex_refs, i)) + "\n";
  return s;
}

// One attribute (the reference) when a triangle has a non-zero reference, none otherwise.
std::string ele_text(const MeshFile& m) {
  const auto& triangles = m.mesh.triangles;
  bool referenced = false;
  for (std::size_t i = 0; i < triangles.size(); ++i) referenced = referenced || ref_of(m.triangle_refs, i) != 0;
  std::string s = std::to_string(triangles.size()) + " 3 " + (referenced ? "1" : "0") + "\n";
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    s += std::to_string(i + 1);
    for (int v : triangles[i]) s += " " + std::to_string(v + 1);
    s += referenced ? " " + std::to_string(ref_of(m.triangle_refs, i)) + "\n" : "\n";
  }
  return s;
}

// The vertices in the .node ("0 2 0 1"), the edges as segments with markers, the holes.
std::string poly_text(const MeshFile& m, const std::string& source) {
  const auto& edges = m.mesh.edges;
  std::string s = "0 2 0 1\n" + std::to_string(edges.size()) + " 1\n";
  for (std::size_t i = 0; i < edges.size(); ++i)
    s += std::to_string(i + 1) + " " + std::to_string(edges[i].first + 1) + " " + std::to_string(edges[i].second + 1) +
         " " + std::to_string(ref_of(m.edge_refs, i)) + "\n";
  s += std::to_string(m.holes.size()) + "\n";
  for (std::size_t i = 0; i < m.holes.size(); ++i)
    s += std::to_string(i + 1) + " " + point_text(m.holes[i], source + ": hole " + std::to_string(i + 1)) + "\n";
  return s;
}

}  // namespace triangle_files
}  // namespace

MeshFile read_triangle(std::string_view node, std::string_view ele, std::string_view poly, const std::string& base) {
  using namespace triangle_files;
  Numbering numbering;
  TextReader node_reader(node, base + ".node", '#');
  Vertices vertices = read_vertices(node_reader, numbering);
  expect_end(node_reader, "vertices", static_cast<std::int64_t>(vertices.sites.size()));
  MeshFile f;
  TextReader ele_reader(ele, base + ".ele", '#');
  read_triangles(ele_reader, numbering, static_cast<std::int64_t>(vertices.sites.size()), f);
  if (!poly.empty()) {
    TextReader poly_reader(poly, base + ".poly", '#');
    read_poly(poly_reader, numbering, vertices, f);
  }
  f.mesh.sites = std::move(vertices.sites);
  f.vertex_refs = std::move(vertices.markers);
  return f;
}

MeshFile read_triangle_files(const std::string& path) {
  using namespace triangle_files;
  const std::string base = base_of(path);
  const std::string node = required_file(path, base + ".node");
  const std::string ele = required_file(path, base + ".ele");
  const std::string poly = std::filesystem::exists(base + ".poly") ? read_whole_file(base + ".poly") : "";
  return read_triangle(node, ele, poly, base);
}

// Metrics, corners, required vertices and edges, ridges: Triangle's files have no place for them.
std::vector<FileText> write_triangle_files(const MeshFile& m, const std::string& path) {
  require_triangle_mesh(m, "Triangle .node/.ele");
  using namespace triangle_files;
  const std::string base = base_of(path);
  std::vector<FileText> files{{base + ".node", node_text(m, base + ".node")}, {base + ".ele", ele_text(m)}};
  if (!m.mesh.edges.empty() || !m.holes.empty()) files.push_back({base + ".poly", poly_text(m, base + ".poly")});
  return files;
}

}  // namespace anisocert::io
