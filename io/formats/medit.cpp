#include "io/formats/medit.hpp"

#include "io/formats/binary_reader.hpp"
#include "io/formats/text_reader.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <cctype>
#include <bit>
#include <cstring>
#include <filesystem>
#include <optional>

namespace anisocert::io {
namespace {

using predicates::Sym2;

// Keyword codes of the binary files (libMeshb's GmfKwdCod enumeration).
enum Code : int {
  version_formatted = 1, dimension = 3, vertices = 4, edges = 5, triangles = 6, quadrilaterals = 7, corners = 13, ridges = 14,
  required_vertices = 15, required_edges = 16, end = 54, sol_at_vertices = 62
};

struct KeywordName {
  Code code;
  const char* name;
};
constexpr KeywordName keyword_names[] = {{dimension, "Dimension"},     {vertices, "Vertices"},
                                         {edges, "Edges"},             {triangles, "Triangles"},
                                         {quadrilaterals, "Quadrilaterals"},
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

int read_dimension(MeditStream& s, const MeditOptions& o) {
  s.set_block("Dimension");
  const std::int64_t d = s.word("the dimension");
  if (d == 3 && !o.allow_planar_3d)
    s.fail("Dimension 3: a planar mesh in 3D is read only when allowed (--planar-3d); every z must then be 0");
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
  bool ended = false;
  std::optional<Code> k;
  while (!ended && (k = s.next_keyword())) {
    s.set_block(name_of(*k));
    const std::int64_t nv = static_cast<std::int64_t>(f.mesh.sites.size());
    switch (*k) {
      case dimension: dim = read_dimension(s, o); break;
      case vertices: {
        if (dim == 0) s.fail("Vertices before Dimension");
        const std::int64_t n = s.count("the vertex count");
        s.check_fits(n, dim * s.real_bytes() + s.int_bytes(), "the vertex");
        f.mesh.sites.reserve(static_cast<std::size_t>(n));
        for (std::int64_t i = 0; i < n; ++i) {
          Rational x = s.real("x"), y = s.real("y");
          if (dim == 3 && s.real("z") != 0) s.fail("vertex " + std::to_string(i + 1) + " has z != 0: the mesh is not planar");
          f.mesh.sites.push_back({std::move(x), std::move(y)});
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
      case quadrilaterals:
        if (s.count("the quadrilateral count") > 0) s.fail("the mesh has quadrilaterals: anisocert certifies meshes of triangles only");
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
  if (f.mesh.sites.empty()) s.fail("no Vertices");
  set_constrained_segments(f);
  return f;
}

std::vector<Sym2<Rational>> read_medit_sol(std::string_view bytes, const std::string& source) {
  MeditStream s(bytes, source);
  std::vector<Sym2<Rational>> metrics;
  int dim = 0;
  bool found = false;
  std::optional<Code> k;
  while ((k = s.next_keyword()) && *k != end) {
    s.set_block(name_of(*k));
    if (*k == dimension) {
      dim = read_dimension(s, MeditOptions{true});
      continue;
    }
    if (*k != sol_at_vertices) s.fail(std::string(name_of(*k)) + " does not belong in a solution file");
    if (dim != 2) s.fail(dim == 0 ? "SolAtVertices before Dimension" : "a metric of Dimension 3 is not a 2D metric");
    const std::int64_t n = s.count("the vertex count");
    const std::int64_t types = s.word("the number of solutions per vertex");
    if (types != 1) s.fail(std::to_string(types) + " solutions per vertex: one metric (type 1 or 3) was expected");
    const std::int64_t type = s.word("the solution type");
    if (type != 1 && type != 3) s.fail("solution type " + std::to_string(type) + " is neither 1 (a size) nor 3 (a symmetric tensor)");
    s.check_fits(n, (type == 1 ? 1 : 3) * s.real_bytes(), "the solution");
    metrics.reserve(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) {
      const std::string at = "vertex " + std::to_string(i + 1);
      if (type == 1) {
        const Rational h = s.real("a size");
        if (h <= 0) s.fail(at + ": the size " + exact_excerpt(h) + " is not positive");
        metrics.push_back(metric_of_size(h));
      } else {
        Rational m11 = s.real("m11"), m12 = s.real("m12"), m22 = s.real("m22");
        Sym2<Rational> m{std::move(m11), std::move(m12), std::move(m22)};
        if (!positive_definite(m))
          s.fail(at + ": the metric [" + exact_excerpt(m.m11) + " " + exact_excerpt(m.m12) + " " +
                 exact_excerpt(m.m22) + "] is not positive definite");
        metrics.push_back(std::move(m));
      }
    }
    found = true;
  }
  s.set_block(nullptr);
  if (!found) s.fail("no SolAtVertices");
  return metrics;
}

MeshFile read_medit_file(const std::string& path, const MeditOptions& o) { return read_medit(read_whole_file(path), path, o); }

std::vector<Sym2<Rational>> read_medit_sol_file(const std::string& path) {
  return read_medit_sol(read_whole_file(path), path);
}

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

void write_dimension(MeditWriter& w) {
  w.keyword(dimension);
  w.word(2);
  w.line_end();
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
  write_dimension(w);
  w.keyword(vertices);
  w.count(static_cast<std::int64_t>(m.mesh.sites.size()));
  for (std::size_t i = 0; i < m.mesh.sites.size(); ++i) {
    const std::string at = "vertex " + std::to_string(i + 1);
    w.real(m.mesh.sites[i].x, at + " x"), w.real(m.mesh.sites[i].y, at + " y");
    w.integer(i < m.vertex_refs.size() ? m.vertex_refs[i] : 0), w.line_end();
  }
  if (!m.mesh.edges.empty()) {
    w.keyword(edges);
    w.count(static_cast<std::int64_t>(m.mesh.edges.size()));
    for (std::size_t i = 0; i < m.mesh.edges.size(); ++i)
      w.integer(m.mesh.edges[i].first + 1), w.integer(m.mesh.edges[i].second + 1),
          w.integer(i < m.edge_refs.size() ? m.edge_refs[i] : 0), w.line_end();
  }
  if (!m.mesh.triangles.empty()) {
    w.keyword(triangles);
    w.count(static_cast<std::int64_t>(m.mesh.triangles.size()));
    for (std::size_t i = 0; i < m.mesh.triangles.size(); ++i) {
      for (int v : m.mesh.triangles[i]) w.integer(v + 1);
      w.integer(i < m.triangle_refs.size() ? m.triangle_refs[i] : 0), w.line_end();
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
  write_dimension(w);
  w.keyword(sol_at_vertices);
  w.count(static_cast<std::int64_t>(metrics.size()));
  w.word(1), w.word(3), w.line_end();  // one solution per vertex, a symmetric tensor: "1 3"
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string at = "metric " + std::to_string(i + 1);
    w.real(metrics[i].m11, at), w.real(metrics[i].m12, at), w.real(metrics[i].m22, at), w.line_end();
  }
  return w.finish();
}

std::vector<FileText> write_medit_file(const MeshFile& m, const std::string& path) {
  const bool binary = path.size() >= 6 && path.compare(path.size() - 6, 6, ".meshb") == 0;
  const MeditEncoding e = binary ? MeditEncoding::binary : MeditEncoding::ascii;
  std::vector<FileText> files{{path, medit_mesh_text(m, e)}};
  if (!m.mesh.metrics.empty()) {
    const std::string sol = std::filesystem::path(path).replace_extension(binary ? ".solb" : ".sol").string();
    files.push_back({sol, medit_sol_text(m.mesh.metrics, e)});
  }
  return files;
}

FileText write_medit_sol(const std::vector<Sym2<Rational>>& metrics, const std::string& path) {
  const bool binary = path.size() >= 5 && path.compare(path.size() - 5, 5, ".solb") == 0;
  return {path, medit_sol_text(metrics, binary ? MeditEncoding::binary : MeditEncoding::ascii)};
}

}  // namespace anisocert::io
