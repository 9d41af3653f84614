#include "io/formats/medit.hpp"

#include "io/formats/binary_reader.hpp"
#include "io/formats/text_reader.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <bit>
#include <cstring>
#include <filesystem>
#include <optional>

namespace anisocert::io {
namespace {

using predicates::Sym2;
using predicates::Sym3;

// Keyword codes of the binary files (libMeshb's GmfKwdCod enumeration).
enum Code : int {
  version_formatted = 1, dimension = 3, vertices = 4, edges = 5, triangles = 6, quadrilaterals = 7, tetrahedra = 8, prisms = 9,
  hexahedra = 10, corners = 13, ridges = 14, required_vertices = 15, required_edges = 16, end = 54, sol_at_vertices = 62
};

struct KeywordName {
  Code code;
  const char* name;
};
constexpr KeywordName keyword_names[] = {{dimension, "Dimension"},     {vertices, "Vertices"},
                                         {edges, "Edges"},             {triangles, "Triangles"},
                                         {quadrilaterals, "Quadrilaterals"}, {tetrahedra, "Tetrahedra"},
                                         {prisms, "Prisms"},           {hexahedra, "Hexahedra"},
                                         {corners, "Corners"},         {ridges, "Ridges"},
                                         {required_vertices, "RequiredVertices"},
                                         {required_edges, "RequiredEdges"}, {end, "End"},
                                         {sol_at_vertices, "SolAtVertices"}};

const char* name_of(int code) {
  for (const auto& k : keyword_names)
    if (k.code == code) return k.name;
  return nullptr;
}

std::optional<Code> code_of(std::string_view name) {
  for (const auto& k : keyword_names)
    if (name == k.name) return k.code;
  return std::nullopt;
}

// The values of one Medit file, text or binary, read through one interface: the keyword loop
// below does not know which. Sizes follow the version (the libMeshb specification): reals are
// 4 bytes in version 1, 8 after; positions 8 bytes from version 3; integers 8 bytes in version 4.
class MeditStream {
 public:
  MeditStream(std::string_view bytes, const std::string& source) : text_(bytes, source, '#'), bin_(bytes, source) {
    binary_ = bytes.size() >= 4 && (bytes.substr(0, 4) == std::string_view("\1\0\0\0", 4) ||
                                    bytes.substr(0, 4) == std::string_view("\0\0\0\1", 4));
    if (!binary_ && !bytes.empty() && static_cast<unsigned char>(bytes[0]) < 0x09)
      bin_.fail_at(0, "the first word is not the byte-order code 1 of a binary Medit file (in either byte order), "
                      "and the file is not text");
    if (binary_) {
      const std::int32_t code = bin_.int32("the byte-order code");
      if (code != 1) bin_.set_swapped(true);
      version_ = bin_.int32("the version");
    } else {
      text_.expect("MeshVersionFormatted");
      version_ = static_cast<int>(text_.integer("the version after MeshVersionFormatted", 1, 4));
    }
    if (version_ < 1 || version_ > 4)
      fail("MeshVersionFormatted " + std::to_string(version_) + " is not one of 1-4 (libMeshb)");
  }

  void set_block(const char* block) {
    text_.set_context(block ? block : "");
    bin_.set_context(block ? block : "");
  }

  // The next keyword (binary: its code, then the position of the next one), or nothing at the end
  // of a text file; unknown keywords are skipped.
  std::optional<Code> next_keyword() {
    for (;;) {
      if (binary_) {
        if (last_) return std::nullopt;
        if (next_ != 0) bin_.seek(next_, "the previous keyword's next-keyword position");
        if (bin_.at_end()) return std::nullopt;
        const std::size_t at = bin_.offset();
        const int code = bin_.int32("a keyword code");
        const std::uint64_t next = version_ >= 3 ? bin_.uint64("a next-keyword position")
                                                 : static_cast<std::uint32_t>(bin_.int32("a next-keyword position"));
        if (next != 0 && next <= at) bin_.fail_at(at, "keyword " + std::to_string(code) + " points back to byte " + std::to_string(next));
        next_ = next;
        last_ = next == 0;
        if (code == end) return end;
        if (name_of(code)) return static_cast<Code>(code);
        if (last_) return std::nullopt;  // an unknown last keyword
        continue;
      }
      if (text_.at_end()) return std::nullopt;
      const std::string_view word = text_.token("a keyword");
      if (const auto c = code_of(word)) return c;
      // An unknown keyword: its data are numbers; skip to the next word that starts with a letter.
      while (!text_.at_end()) {
        const std::string_view t = text_.peek();
        if (std::isalpha(static_cast<unsigned char>(t.front()))) break;
        text_.token("");
      }
    }
  }

  std::int64_t count(const char* what) {
    if (binary_) {
      const std::size_t at = bin_.offset();
      const std::int64_t n = version_ == 4 ? bin_.int64(what) : bin_.int32(what);
      if (n < 0) bin_.fail_at(at, std::string(what) + " is negative");
      return n;
    }
    return text_.integer(what, 0, INT64_MAX);
  }

  std::int64_t integer(const char* what) {
    if (binary_) return version_ == 4 ? bin_.int64(what) : bin_.int32(what);
    return text_.integer(what, INT64_MIN, INT64_MAX);
  }
  // A 32-bit word in every binary version: the dimension, a solution's number of types and types.
  std::int64_t word(const char* what) {
    if (binary_) return bin_.int32(what);
    return text_.integer(what, INT32_MIN, INT32_MAX);
  }

  // A vertex index (1-based in the file) as a site index.
  int index(const char* what, std::int64_t n) {
    const std::size_t at = bin_.offset();
    const std::int64_t i = integer(what);
    if (i < 1 || i > n) fail_at(at, std::string(what) + " " + std::to_string(i) + " is not a vertex (1.." + std::to_string(n) + ")");
    return static_cast<int>(i - 1);
  }

  Rational real(const char* what) {
    if (binary_) return bin_.real(version_ == 1 ? 4 : 8, what);
    return text_.number(what);
  }

  // Guards against a hostile count: every entry takes at least min_bytes bytes (binary) or two
  // characters (text), so a count larger than the file allows is refused before any allocation.
  void check_fits(std::int64_t n, std::size_t min_bytes, const char* what) {
    const std::size_t room = binary_ ? (bin_.size() - bin_.offset()) / min_bytes : bin_.size() / 2;
    if (static_cast<std::uint64_t>(n) > room) fail(std::string(what) + " count " + std::to_string(n) + " exceeds what the file can hold");
  }
  std::size_t real_bytes() const { return version_ == 1 ? 4 : 8; }
  std::size_t int_bytes() const { return version_ == 4 ? 8 : 4; }

  [[noreturn]] void fail(const std::string& what) const { fail_at(bin_.offset(), what); }
  [[noreturn]] void fail_at(std::size_t byte, const std::string& what) const {
    if (binary_) bin_.fail_at(byte, what);
    text_.fail(what);
  }

 private:
  TextReader text_;
  BinaryReader bin_;
  bool binary_ = false;
  int version_ = 0;
  std::uint64_t next_ = 0;
  bool last_ = false;
};

int read_dimension(MeditStream& s) {
  s.set_block("Dimension");
  const std::int64_t d = s.word("the dimension");
  if (d != 2 && d != 3) s.fail("Dimension " + std::to_string(d) + " is neither 2 nor 3");
  return static_cast<int>(d);
}

// A list of vertex indices (Corners, RequiredVertices) or edge indices (RequiredEdges, Ridges).
std::vector<int> read_index_list(MeditStream& s, std::int64_t range, const char* what) {
  const std::int64_t n = s.count("the count");
  s.check_fits(n, s.int_bytes(), what);
  std::vector<int> v;
  v.reserve(static_cast<std::size_t>(n));
  for (std::int64_t k = 0; k < n; ++k) v.push_back(s.index(what, range));
  return v;
}

int read_ref(MeditStream& s) {
  const std::int64_t r = s.integer("a reference");
  return static_cast<int>(std::clamp<std::int64_t>(r, INT32_MIN, INT32_MAX));
}

}  // namespace

MeshFile read_medit(std::string_view bytes, const std::string& source, const MeditOptions& o) {
  MeditStream s(bytes, source);
  MeshFile f;
  int dim = 0;
  std::vector<predicates::Point3<Rational>> vertices3;  // Dimension 3: decided at the end
  bool ended = false;
  std::optional<Code> k;
  while (!ended && (k = s.next_keyword())) {
    s.set_block(name_of(*k));
    const std::int64_t nv = static_cast<std::int64_t>(dim == 3 ? vertices3.size() : f.mesh.sites.size());
    switch (*k) {
      case dimension: dim = read_dimension(s); break;
      case vertices: {
        if (dim == 0) s.fail("Vertices before Dimension");
        const std::int64_t n = s.count("the vertex count");
        s.check_fits(n, dim * s.real_bytes() + s.int_bytes(), "the vertex");
        if (dim == 3) vertices3.reserve(static_cast<std::size_t>(n));
        else f.mesh.sites.reserve(static_cast<std::size_t>(n));
        for (std::int64_t i = 0; i < n; ++i) {
          Rational x = s.real("x"), y = s.real("y");
          if (dim == 3) vertices3.push_back({std::move(x), std::move(y), s.real("z")});
          else f.mesh.sites.push_back({std::move(x), std::move(y)});
          f.vertex_refs.push_back(read_ref(s));
        }
        break;
      }
      case edges: {
        const std::int64_t n = s.count("the edge count");
        s.check_fits(n, 3 * s.int_bytes(), "the edge");
        for (std::int64_t i = 0; i < n; ++i) {
          const int a = s.index("an edge's vertex", nv), b = s.index("an edge's vertex", nv);
          f.mesh.edges.emplace_back(a, b);
          f.edge_refs.push_back(read_ref(s));
        }
        break;
      }
      case triangles: {
        const std::int64_t n = s.count("the triangle count");
        s.check_fits(n, 4 * s.int_bytes(), "the triangle");
        f.mesh.triangles.reserve(static_cast<std::size_t>(n));
        for (std::int64_t i = 0; i < n; ++i) {
          const int a = s.index("a triangle's vertex", nv), b = s.index("a triangle's vertex", nv),
                    c = s.index("a triangle's vertex", nv);
          f.mesh.triangles.push_back({a, b, c});
          f.triangle_refs.push_back(read_ref(s));
        }
        break;
      }
      case tetrahedra: {
        const std::int64_t n = s.count("the tetrahedron count");
        if (n > 0 && dim != 3) s.fail("Tetrahedra in a mesh of Dimension " + std::to_string(dim));  // MMG writes "Tetrahedra 0" in 2D
        s.check_fits(n, 5 * s.int_bytes(), "the tetrahedron");
        f.mesh3.tetrahedra.reserve(static_cast<std::size_t>(n));
        for (std::int64_t i = 0; i < n; ++i) {
          const int a = s.index("a tetrahedron's vertex", nv), b = s.index("a tetrahedron's vertex", nv),
                    c = s.index("a tetrahedron's vertex", nv), d = s.index("a tetrahedron's vertex", nv);
          f.mesh3.tetrahedra.push_back({a, b, c, d});
          f.tetrahedron_refs.push_back(read_ref(s));
        }
        break;
      }
      case quadrilaterals:
      case prisms:
      case hexahedra:
        if (s.count("the element count") > 0)
          s.fail(std::string("the mesh has ") + (*k == quadrilaterals ? "quadrilaterals" : *k == prisms ? "prisms" : "hexahedra") +
                 ": anisocert certifies meshes of triangles or tetrahedra only");
        break;
      case corners: f.corners = read_index_list(s, nv, "a corner"); break;
      case required_vertices: f.required_vertices = read_index_list(s, nv, "a required vertex"); break;
      case required_edges:
        f.required_edges = read_index_list(s, static_cast<std::int64_t>(f.mesh.edges.size()), "a required edge");
        break;
      case ridges: f.ridges = read_index_list(s, static_cast<std::int64_t>(f.mesh.edges.size()), "a ridge"); break;
      case end: ended = true; break;
      default: s.fail(std::string(name_of(*k)) + " does not belong in a mesh file");
    }
  }
  s.set_block(nullptr);
  if (dim == 0) s.fail("no Dimension keyword");
  if (dim == 3) {
    // Dimension 3: a tetrahedral mesh when it has tetrahedra; without, a planar one (every z = 0)
    // when allowed; a surface mesh otherwise, which anisocert does not certify.
    if (vertices3.empty()) s.fail("no Vertices");
    if (!f.mesh3.tetrahedra.empty()) {
      f.dimension = 3;
      f.mesh3.vertices = std::move(vertices3);
      f.mesh3.triangles = std::move(f.mesh.triangles);
      f.mesh.triangles.clear();
      return f;
    }
    if (o.allow_surface) {
      f.dimension = 3;
      f.mesh3.vertices = std::move(vertices3);
      f.mesh3.triangles = std::move(f.mesh.triangles);
      f.mesh.triangles.clear();
      return f;
    }
    const auto lifted = std::find_if(vertices3.begin(), vertices3.end(), [](const auto& p) { return p.z != 0; });
    if (lifted != vertices3.end())
      s.fail("Dimension 3 with no Tetrahedra, and vertex " + std::to_string(lifted - vertices3.begin() + 1) +
             " has z != 0: a surface mesh, neither planar nor tetrahedral");
    if (!o.allow_planar_3d)
      s.fail("Dimension 3 with every z = 0 and no Tetrahedra: a planar mesh in 3D is read only when allowed (--planar-3d)");
    for (auto& p : vertices3) f.mesh.sites.push_back({std::move(p.x), std::move(p.y)});
  }
  if (f.mesh.sites.empty()) s.fail("no Vertices");
  set_constrained_segments(f);
  return f;
}

namespace {

// The metric of a size h > 0 in dimension 2 or 3: I / h².
Sym2<Rational> of_size(const Rational& h, Sym2<Rational>*) { return metric_of_size(h); }
Sym3<Rational> of_size(const Rational& h, Sym3<Rational>*) { return metric3_of_size(h); }
// A symmetric tensor in the file's order: the lower triangle by rows, m11 m12 m22 (2D), m11 m12 m22
// m13 m23 m33 (3D).
Sym2<Rational> tensor(MeditStream& s, Sym2<Rational>*) {
  Rational m11 = s.real("m11"), m12 = s.real("m12"), m22 = s.real("m22");
  return {std::move(m11), std::move(m12), std::move(m22)};
}
Sym3<Rational> tensor(MeditStream& s, Sym3<Rational>*) {
  Rational m11 = s.real("m11"), m12 = s.real("m12"), m22 = s.real("m22"), m13 = s.real("m13"), m23 = s.real("m23"), m33 = s.real("m33");
  return {std::move(m11), std::move(m12), std::move(m13), std::move(m22), std::move(m23), std::move(m33)};
}
std::string text(const Sym2<Rational>& m) { return exact_excerpt(m.m11) + " " + exact_excerpt(m.m12) + " " + exact_excerpt(m.m22); }
std::string text(const Sym3<Rational>& m) {
  return exact_excerpt(m.m11) + " " + exact_excerpt(m.m12) + " " + exact_excerpt(m.m22) + " " + exact_excerpt(m.m13) + " " +
         exact_excerpt(m.m23) + " " + exact_excerpt(m.m33);
}
bool is_positive_definite(const Sym2<Rational>& m) { return positive_definite(m); }
bool is_positive_definite(const Sym3<Rational>& m) { return predicates::positive_definite(m); }

// SolAtVertices of a .sol of dimension D (2: Sym2, 3: Sym3).
template <class Sym, int D>
std::vector<Sym> read_sol(std::string_view bytes, const std::string& source) {
  MeditStream s(bytes, source);
  std::vector<Sym> metrics;
  int dim = 0;
  bool found = false;
  std::optional<Code> k;
  while ((k = s.next_keyword()) && *k != end) {
    s.set_block(name_of(*k));
    if (*k == dimension) {
      dim = read_dimension(s);
      continue;
    }
    if (*k != sol_at_vertices) s.fail(std::string(name_of(*k)) + " does not belong in a solution file");
    if (dim != D)
      s.fail(dim == 0 ? std::string("SolAtVertices before Dimension")
                      : "a metric of Dimension " + std::to_string(dim) + " is not a " + std::to_string(D) + "D metric");
    const std::int64_t n = s.count("the vertex count");
    const std::int64_t types = s.word("the number of solutions per vertex");
    if (types != 1) s.fail(std::to_string(types) + " solutions per vertex: one metric (type 1 or 3) was expected");
    const std::int64_t type = s.word("the solution type");
    if (type != 1 && type != 3) s.fail("solution type " + std::to_string(type) + " is neither 1 (a size) nor 3 (a symmetric tensor)");
    s.check_fits(n, (type == 1 ? 1 : D * (D + 1) / 2) * s.real_bytes(), "the solution");
    metrics.reserve(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) {
      const std::string at = "vertex " + std::to_string(i + 1);
      if (type == 1) {
        const Rational h = s.real("a size");
        if (h <= 0) s.fail(at + ": the size " + exact_excerpt(h) + " is not positive");
        metrics.push_back(of_size(h, static_cast<Sym*>(nullptr)));
      } else {
        Sym m = tensor(s, static_cast<Sym*>(nullptr));
        if (!is_positive_definite(m)) s.fail(at + ": the metric [" + text(m) + "] is not positive definite");
        metrics.push_back(std::move(m));
      }
    }
    found = true;
  }
  s.set_block(nullptr);
  if (!found) s.fail("no SolAtVertices");
  return metrics;
}

}  // namespace

std::vector<Sym2<Rational>> read_medit_sol(std::string_view bytes, const std::string& source) {
  return read_sol<Sym2<Rational>, 2>(bytes, source);
}

std::vector<Sym3<Rational>> read_medit_sol3(std::string_view bytes, const std::string& source) {
  return read_sol<Sym3<Rational>, 3>(bytes, source);
}

MeshFile read_medit_file(const std::string& path, const MeditOptions& o) { return read_medit(read_whole_file(path), path, o); }

std::vector<Sym2<Rational>> read_medit_sol_file(const std::string& path) {
  return read_medit_sol(read_whole_file(path), path);
}

std::vector<Sym3<Rational>> read_medit_sol3_file(const std::string& path) { return read_medit_sol3(read_whole_file(path), path); }

// --- writers ---------------------------------------------------------------------------------

namespace {

// The writer's side of MeditStream: the same layout, text or binary.
class MeditWriter {
 public:
  MeditWriter(MeditEncoding e, int version) : binary_(e == MeditEncoding::binary), version_(version) {
    if (version < 1 || version > 4) throw InputError("Medit version " + std::to_string(version) + " is not one of 1-4");
    if (binary_) {
      put32(1), put32(version);
    } else {
      out_ += "MeshVersionFormatted " + std::to_string(version) + "\n";
    }
  }
  void keyword(Code c) {
    if (!binary_) {
      out_ += std::string(name_of(c)) + "\n";
      return;
    }
    patch_next();
    put32(c);
    next_at_ = out_.size();
    if (version_ >= 3) put64(0); else put32(0);
    if (c == end) next_at_ = 0;  // End's next position stays 0
  }
  void count(std::int64_t n) {
    if (binary_) version_ == 4 ? put64(n) : put32(static_cast<std::int32_t>(n));
    else out_ += std::to_string(n) + "\n";
  }
  void integer(std::int64_t v) {
    if (binary_) version_ == 4 ? put64(v) : put32(static_cast<std::int32_t>(v));
    else out_ += std::to_string(v) + " ";
  }
  void word(std::int32_t v) {
    if (binary_) put32(v);
    else out_ += std::to_string(v) + " ";
  }
  void real(const Rational& q, const std::string& what) {
    if (!binary_) {
      out_ += decimal_text(q, what) + " ";
    } else if (version_ == 1) {
      const double d = exact_double(q, what);
      const float f = static_cast<float>(d);
      if (static_cast<double>(f) != d) throw InputError(what + " = " + exact_excerpt(q) + " is not a float: version 1 cannot hold it");
      put32(std::bit_cast<std::int32_t>(f));
    } else {
      put64(std::bit_cast<std::int64_t>(exact_double(q, what)));
    }
  }
  void line_end() {
    if (!binary_) out_.back() = '\n';
  }
  std::string finish() {
    keyword(end);
    return std::move(out_);
  }

 private:
  void patch_next() {
    if (next_at_ == 0) return;
    const std::uint64_t here = out_.size();
    if (version_ >= 3) std::memcpy(out_.data() + next_at_, &here, 8);
    else {
      const std::uint32_t h = static_cast<std::uint32_t>(here);
      std::memcpy(out_.data() + next_at_, &h, 4);
    }
  }
  void put32(std::int32_t v) { out_.append(reinterpret_cast<const char*>(&v), 4); }
  void put64(std::int64_t v) { out_.append(reinterpret_cast<const char*>(&v), 8); }
  bool binary_;
  int version_;
  std::string out_;
  std::size_t next_at_ = 0;
};

void write_dimension(MeditWriter& w, int d) {
  w.keyword(dimension);
  w.word(d);
  w.line_end();
}

void write_triangles(MeditWriter& w, const std::vector<std::array<int, 3>>& list, const std::vector<int>& refs) {
  if (list.empty()) return;
  w.keyword(triangles);
  w.count(static_cast<std::int64_t>(list.size()));
  for (std::size_t i = 0; i < list.size(); ++i) {
    for (int v : list[i]) w.integer(v + 1);
    w.integer(i < refs.size() ? refs[i] : 0), w.line_end();
  }
}

void write_index_list(MeditWriter& w, Code c, const std::vector<int>& list) {
  if (list.empty()) return;
  w.keyword(c);
  w.count(static_cast<std::int64_t>(list.size()));
  for (int i : list) w.integer(i + 1), w.line_end();
}

}  // namespace

std::string medit_mesh_text(const MeshFile& m, MeditEncoding e, int version) {
  MeditWriter w(e, version);
  const bool three = m.dimension == 3;
  write_dimension(w, three ? 3 : 2);
  w.keyword(vertices);
  const std::size_t n = three ? m.mesh3.vertices.size() : m.mesh.sites.size();
  w.count(static_cast<std::int64_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = "vertex " + std::to_string(i + 1);
    if (three) {
      w.real(m.mesh3.vertices[i].x, at + " x"), w.real(m.mesh3.vertices[i].y, at + " y"), w.real(m.mesh3.vertices[i].z, at + " z");
    } else {
      w.real(m.mesh.sites[i].x, at + " x"), w.real(m.mesh.sites[i].y, at + " y");
    }
    w.integer(i < m.vertex_refs.size() ? m.vertex_refs[i] : 0), w.line_end();
  }
  if (!m.mesh.edges.empty()) {
    w.keyword(edges);
    w.count(static_cast<std::int64_t>(m.mesh.edges.size()));
    for (std::size_t i = 0; i < m.mesh.edges.size(); ++i)
      w.integer(m.mesh.edges[i].first + 1), w.integer(m.mesh.edges[i].second + 1),
          w.integer(i < m.edge_refs.size() ? m.edge_refs[i] : 0), w.line_end();
  }
  write_triangles(w, three ? m.mesh3.triangles : m.mesh.triangles, m.triangle_refs);
  if (three && !m.mesh3.tetrahedra.empty()) {
    w.keyword(tetrahedra);
    w.count(static_cast<std::int64_t>(m.mesh3.tetrahedra.size()));
    for (std::size_t i = 0; i < m.mesh3.tetrahedra.size(); ++i) {
      for (int v : m.mesh3.tetrahedra[i]) w.integer(v + 1);
      w.integer(i < m.tetrahedron_refs.size() ? m.tetrahedron_refs[i] : 0), w.line_end();
    }
  }
  write_index_list(w, corners, m.corners);
  write_index_list(w, required_vertices, m.required_vertices);
  write_index_list(w, required_edges, m.required_edges);
  write_index_list(w, ridges, m.ridges);
  return w.finish();
}

std::string medit_sol_text(const std::vector<Sym2<Rational>>& metrics, MeditEncoding e, int version) {
  MeditWriter w(e, version);
  write_dimension(w, 2);
  w.keyword(sol_at_vertices);
  w.count(static_cast<std::int64_t>(metrics.size()));
  w.word(1), w.word(3), w.line_end();  // one solution per vertex, a symmetric tensor: "1 3"
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string at = "metric " + std::to_string(i + 1);
    w.real(metrics[i].m11, at), w.real(metrics[i].m12, at), w.real(metrics[i].m22, at), w.line_end();
  }
  return w.finish();
}

std::string medit_sol_text(const std::vector<Sym3<Rational>>& metrics, MeditEncoding e, int version) {
  MeditWriter w(e, version);
  write_dimension(w, 3);
  w.keyword(sol_at_vertices);
  w.count(static_cast<std::int64_t>(metrics.size()));
  w.word(1), w.word(3), w.line_end();
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string at = "metric " + std::to_string(i + 1);
    const Sym3<Rational>& m = metrics[i];
    w.real(m.m11, at), w.real(m.m12, at), w.real(m.m22, at), w.real(m.m13, at), w.real(m.m23, at), w.real(m.m33, at), w.line_end();
  }
  return w.finish();
}

std::vector<FileText> write_medit_file(const MeshFile& m, const std::string& path) {
  const bool binary = path.size() >= 6 && path.compare(path.size() - 6, 6, ".meshb") == 0;
  const MeditEncoding e = binary ? MeditEncoding::binary : MeditEncoding::ascii;
  std::vector<FileText> files{{path, medit_mesh_text(m, e)}};
  const std::string sol = std::filesystem::path(path).replace_extension(binary ? ".solb" : ".sol").string();
  if (m.dimension == 3 && !m.mesh3.metrics.empty()) files.push_back({sol, medit_sol_text(m.mesh3.metrics, e)});
  if (m.dimension != 3 && !m.mesh.metrics.empty()) files.push_back({sol, medit_sol_text(m.mesh.metrics, e)});
  return files;
}

namespace {

template <class M>
FileText sol_file(const std::vector<M>& metrics, const std::string& path) {
  const bool binary = path.size() >= 5 && path.compare(path.size() - 5, 5, ".solb") == 0;
  return {path, medit_sol_text(metrics, binary ? MeditEncoding::binary : MeditEncoding::ascii)};
}

}  // namespace

FileText write_medit_sol(const std::vector<Sym2<Rational>>& metrics, const std::string& path) { return sol_file(metrics, path); }
FileText write_medit_sol3(const std::vector<Sym3<Rational>>& metrics, const std::string& path) { return sol_file(metrics, path); }

}  // namespace anisocert::io
