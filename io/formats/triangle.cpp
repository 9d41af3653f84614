// Shewchuk's Triangle files as its pages define them: https://www.cs.cmu.edu/~quake/triangle.node.html,
// triangle.ele.html and triangle.poly.html; and their 3D sibling, Si's TetGen (the TetGen 1.5
// manual, § 5.2: .node of dimension 3, .ele of 4-node tetrahedra with an optional region
// attribute, .face of boundary faces with an optional marker), read by the same code. Choices
// where the pages leave room:
// - every list of the three files (vertices, triangles, segments, holes, regions) is numbered
//   consecutively from the base the first vertex sets (0 or 1), as Triangle writes them;
// - 6-node triangles (Triangle's -o2) and 10-node tetrahedra (TetGen's -o2) are refused: the
//   certifier takes linear simplices, and the midpoint vertices would be sites of no element;
// - the dimension of the .node decides: 2, Triangle's files (.ele of triangles, .poly of
//   segments and holes); 3, TetGen's (.ele of tetrahedra, .face of the declared boundary faces;
//   a .poly or .smesh beside them is TetGen's input, not read);
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
using predicates::Point3;

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
  int dimension = 2;
  std::vector<Point2<Rational>> sites;   // dimension 2
  std::vector<Point3<Rational>> points;  // dimension 3
  std::vector<int> markers;  // 0 without a marker column
  std::size_t size() const { return dimension == 3 ? points.size() : sites.size(); }
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
// [boundary marker]"; TetGen's .node the same with dimension 3 and "<x> <y> <z>". `planar`: a
// .poly's vertex list, which is Triangle's only.
Vertices read_vertices(TextReader& r, Numbering& numbering, bool planar) {
  const std::int64_t n = read_count(r, "vertex header: number of vertices");
  const std::int64_t dimension = r.integer("vertex header: dimension", INT64_MIN, INT64_MAX);
  if (dimension != 2 && (planar || dimension != 3))
    r.fail("vertex header: dimension " + std::to_string(dimension) +
           (planar ? ": Triangle's files are planar (dimension 2)" : ": Triangle's files are planar (2), TetGen's spatial (3)"));
  const std::int64_t attributes = read_count(r, "vertex header: number of attributes");
  const bool marked = r.integer("vertex header: number of boundary markers", 0, 1) == 1;
  Vertices v;
  v.dimension = static_cast<int>(dimension);
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "vertex", i);
    Rational x = r.number(what + ": x"), y = r.number(what + ": y");
    if (dimension == 3) v.points.push_back({std::move(x), std::move(y), r.number(what + ": z")});
    else v.sites.push_back({std::move(x), std::move(y)});
    read_attributes(r, what, attributes);
    v.markers.push_back(marked ? read_marker(r, what) : 0);
  }
  return v;
}

// triangle.ele.html: "<# of triangles> <nodes per triangle> <# of attributes>", then
// "<triangle #> <node> <node> <node> ... [attributes]", corners counterclockwise; TetGen's .ele:
// "<# of tetrahedra> <nodes per tetrahedron (4 or 10)> <region attribute (0 or 1)>", then
// "<tetrahedron #> <node> <node> <node> <node> ... [attribute]".
template <std::size_t K>
void read_elements(TextReader& r, Numbering& numbering, std::int64_t nv, std::vector<std::array<int, K>>& elements,
                   std::vector<int>& refs) {
  const bool tetrahedra = K == 4;
  const std::string kind = tetrahedra ? "tetrahedron" : "triangle", header = kind + " header: ";
  const std::int64_t n = read_count(r, header + "number of " + (tetrahedra ? "tetrahedra" : "triangles"));
  const std::int64_t nodes = r.integer(header + "nodes per " + kind, INT64_MIN, INT64_MAX);
  if (nodes == (tetrahedra ? 10 : 6))
    r.fail(header + std::to_string(nodes) + " nodes per " + kind + " (" + (tetrahedra ? "TetGen" : "Triangle") +
           "'s -o2 quadratic elements) are not read: anisocert certifies linear " + (tetrahedra ? "tetrahedra" : "triangles"));
  if (nodes != static_cast<std::int64_t>(K))
    r.fail(header + std::to_string(nodes) + " nodes per " + kind + ", where " + (tetrahedra ? "TetGen" : "Triangle") +
           " writes " + std::to_string(K));
  const std::int64_t attributes = read_count(r, header + "number of attributes");
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, kind, i);
    std::array<int, K> t{};
    for (int& corner : t) corner = numbering.vertex(r, what + ": corner", nv);
    elements.push_back(t);
    refs.push_back(reference_of(read_attributes(r, what, attributes)));
  }
  expect_end(r, tetrahedra ? "tetrahedra" : "triangles", n);
}

// TetGen's .face: "<# of faces> <boundary marker (0 or 1)>", then "<face #> <node> <node> <node>
// [boundary marker]": the mesh's declared boundary faces.
void read_faces(TextReader& r, Numbering& numbering, std::int64_t nv, MeshFile& f) {
  const std::int64_t n = read_count(r, "face header: number of faces");
  const bool marked = r.integer("face header: number of boundary markers", 0, 1) == 1;
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string what = numbering.entry(r, "face", i);
    std::array<int, 3> t{};
    for (int& corner : t) corner = numbering.vertex(r, what + ": corner", nv);
    f.mesh3.triangles.push_back(t);
    f.triangle_refs.push_back(marked ? read_marker(r, what) : 0);
  }
  expect_end(r, "faces", n);
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
  const Vertices own = read_vertices(r, numbering, true);
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
  return e == ".node" || e == ".ele" || e == ".poly" || e == ".face" ? std::filesystem::path(p).replace_extension().string() : path;
}

// A file the mesh cannot be read without, named with the path the user gave.
std::string required_file(const std::string& given, const std::string& file) {
  if (!std::filesystem::exists(file))
    throw InputError(given + ": the Triangle or TetGen mesh needs " + file + ", which does not exist");
  return read_whole_file(file);
}

// A reference of a writer's list: 0 when the mesh has none (MeshFile: "0 when the format has none").
int ref_of(const std::vector<int>& refs, std::size_t i) { return i < refs.size() ? refs[i] : 0; }

std::string point_text(const Point2<Rational>& p, const std::string& what) {
  return decimal_text(p.x, what + ": x") + " " + decimal_text(p.y, what + ": y");
}

std::string point_text(const Point3<Rational>& p, const std::string& what) {
  return decimal_text(p.x, what + ": x") + " " + decimal_text(p.y, what + ": y") + " " + decimal_text(p.z, what + ": z");
}

// Written numbered from 1, Triangle's and TetGen's default (-z numbers from 0), with a boundary
// marker column.
template <class P>
std::string node_text(const MeshFile& m, const std::vector<P>& points, const std::string& source) {
  std::string s = std::to_string(points.size()) + (m.dimension == 3 ? " 3 0 1\n" : " 2 0 1\n");
  for (std::size_t i = 0; i < points.size(); ++i)
    s += std::to_string(i + 1) + " " + point_text(points[i], source + ": vertex " + std::to_string(i + 1)) + " " +
         std::to_string(ref_of(m.vertex_refs, i)) + "\n";
  return s;
}

// One attribute (the reference) when an element has a non-zero reference, none otherwise.
template <std::size_t K>
std::string ele_text(const std::vector<std::array<int, K>>& elements, const std::vector<int>& refs) {
  bool referenced = false;
  for (std::size_t i = 0; i < elements.size(); ++i) referenced = referenced || ref_of(refs, i) != 0;
  std::string s = std::to_string(elements.size()) + " " + std::to_string(K) + " " + (referenced ? "1" : "0") + "\n";
  for (std::size_t i = 0; i < elements.size(); ++i) {
    s += std::to_string(i + 1);
    for (int v : elements[i]) s += " " + std::to_string(v + 1);
    s += referenced ? " " + std::to_string(ref_of(refs, i)) + "\n" : "\n";
  }
  return s;
}

// TetGen's .face: the declared faces with their markers.
std::string face_text(const MeshFile& m) {
  const auto& faces = m.mesh3.triangles;
  std::string s = std::to_string(faces.size()) + " 1\n";
  for (std::size_t i = 0; i < faces.size(); ++i) {
    s += std::to_string(i + 1);
    for (int v : faces[i]) s += " " + std::to_string(v + 1);
    s += " " + std::to_string(ref_of(m.triangle_refs, i)) + "\n";
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

MeshFile read_triangle(std::string_view node, std::string_view ele, std::string_view poly, const std::string& base,
                       std::string_view face) {
  using namespace triangle_files;
  Numbering numbering;
  TextReader node_reader(node, base + ".node", '#');
  Vertices vertices = read_vertices(node_reader, numbering, false);
  const auto nv = static_cast<std::int64_t>(vertices.size());
  expect_end(node_reader, "vertices", nv);
  MeshFile f;
  TextReader ele_reader(ele, base + ".ele", '#');
  if (vertices.dimension == 3) {
    f.dimension = 3;
    read_elements(ele_reader, numbering, nv, f.mesh3.tetrahedra, f.tetrahedron_refs);
    if (!face.empty()) {
      TextReader face_reader(face, base + ".face", '#');
      read_faces(face_reader, numbering, nv, f);
    }
    f.mesh3.vertices = std::move(vertices.points);
    f.vertex_refs = std::move(vertices.markers);
    return f;
  }
  read_elements(ele_reader, numbering, nv, f.mesh.triangles, f.triangle_refs);
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
  const std::string face = std::filesystem::exists(base + ".face") ? read_whole_file(base + ".face") : "";
  return read_triangle(node, ele, poly, base, face);
}

// Metrics, corners, required vertices and edges, ridges: Triangle's and TetGen's files have no
// place for them. A tetrahedral mesh is written as TetGen's .node/.ele/.face.
std::vector<FileText> write_triangle_files(const MeshFile& m, const std::string& path) {
  using namespace triangle_files;
  const std::string base = base_of(path);
  if (m.dimension == 3)
    return {{base + ".node", node_text(m, m.mesh3.vertices, base + ".node")},
            {base + ".ele", ele_text(m.mesh3.tetrahedra, m.tetrahedron_refs)},
            {base + ".face", face_text(m)}};
  std::vector<FileText> files{{base + ".node", node_text(m, m.mesh.sites, base + ".node")},
                              {base + ".ele", ele_text(m.mesh.triangles, m.triangle_refs)}};
  if (!m.mesh.edges.empty() || !m.holes.empty()) files.push_back({base + ".poly", poly_text(m, base + ".poly")});
  return files;
}

}  // namespace anisocert::io
