// FreeFem++'s .msh (the FreeFem++ documentation, "Mesh generation", "Data structures and read/write
// statements for a mesh": "nv nt nbe", nv lines "x y label", nt lines "i j k label", nbe lines
// "i j label", vertex numbers from 1), as savemesh and bamg -omsh write it, and BAMG's metric file
// (bamg's -M/-oM: "nbv 1" then a size h per vertex, or "nbv 3" then "a11 a21 a22" per vertex).
// Every count must match the entries exactly: nothing but blanks may follow the last one.
#include "io/formats/freefem.hpp"

#include "io/formats/text_reader.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <filesystem>

namespace anisocert::io {
namespace {
namespace freefem_files {

using predicates::Sym2;

std::int64_t read_count(TextReader& r, const std::string& what) { return r.integer("header: " + what, 0, INT_MAX); }

int read_label(TextReader& r, const std::string& what) {
  return static_cast<int>(r.integer(what + ": label", INT_MIN, INT_MAX));
}

// A vertex number of the file (from 1, among nv) as a site index.
int read_vertex(TextReader& r, const std::string& what, std::int64_t nv) {
  const std::int64_t k = r.integer(what, INT64_MIN, INT64_MAX);
  if (k < 1 || k > nv) r.fail(what + " " + std::to_string(k) + " is out of range (vertices 1.." + std::to_string(nv) + ")");
  return static_cast<int>(k - 1);
}

// Nothing but blanks after the declared entries.
void expect_end(TextReader& r, const std::string& section, std::int64_t declared) {
  if (!r.at_end())
    r.fail(section + ": more data than the header declares (" + std::to_string(declared) + "): " +
           quoted_excerpt(r.peek()));
}

std::string entry(const char* kind, std::int64_t i) { return kind + std::string(" ") + std::to_string(i + 1); }

// "nbv 1": a size h > 0, the metric I/h².
Sym2<Rational> read_size(TextReader& r, const std::string& what) {
  const Rational h = r.number(what + ": size h");
  if (h <= 0) r.fail(what + ": size h = " + exact_excerpt(h) + " is not positive (the metric is I/h²)");
  return metric_of_size(h);
}

// "nbv 3": a11 a21 a22 (bamg's MetricAnIso), symmetric positive definite.
Sym2<Rational> read_tensor(TextReader& r, const std::string& what) {
  Sym2<Rational> m{r.number(what + ": a11"), r.number(what + ": a21"), r.number(what + ": a22")};
  if (!positive_definite(m))
    r.fail(what + ": metric a11 a21 a22 = " + exact_excerpt(m.m11) + " " + exact_excerpt(m.m12) + " " +
           exact_excerpt(m.m22) + " is not positive definite (a11 > 0 and a11 a22 - a21² > 0 required)");
  return m;
}

// A label of a writer's list: 0 when the mesh has none (MeshFile: "0 when the format has none").
int ref_of(const std::vector<int>& refs, std::size_t i) { return i < refs.size() ? refs[i] : 0; }

// "nv nt nbe", then "x y label", "i j k label" and "i j label" lines, vertices numbered from 1.
std::string msh_text(const MeshFile& m, const std::string& source) {
  const auto& g = m.mesh;
  std::string s = std::to_string(g.sites.size()) + " " + std::to_string(g.triangles.size()) + " " +
                  std::to_string(g.edges.size()) + "\n";
  for (std::size_t i = 0; i < g.sites.size(); ++i) {
    const std::string what = source + ": " + entry("vertex", static_cast<std::int64_t>(i));
    s += decimal_text(g.sites[i].x, what + ": x") + " " + decimal_text(g.sites[i].y, what + ": y") + " " +
         std::to_string(ref_of(m.vertex_refs, i)) + "\n";
  }
  for (std::size_t i = 0; i < g.triangles.size(); ++i) {
    for (int v : g.triangles[i]) s += std::to_string(v + 1) + " ";
    s += std::to_string(ref_of(m.triangle_refs, i)) + "\n";
  }
  for (std::size_t i = 0; i < g.edges.size(); ++i)
    s += std::to_string(g.edges[i].first + 1) + " " + std::to_string(g.edges[i].second + 1) + " " +
         std::to_string(ref_of(m.edge_refs, i)) + "\n";
  return s;
}

// A non-empty run of decimal digits.
bool digits(std::string_view t) {
  for (char c : t)
    if (c < '0' || c > '9') return false;
  return !t.empty();
}

}  // namespace freefem_files
}  // namespace

// Gmsh's .msh starts with "$MeshFormat" (or "$NOD"), FreeFem's with the three counts "nv nt nbe".
bool looks_like_freefem(std::string_view head) {
  constexpr std::string_view blanks = " \t\r\n";
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    at = head.find_first_not_of(blanks, at);
    if (at == std::string_view::npos) return false;
    const std::size_t end = std::min(head.find_first_of(blanks, at), head.size());
    if (!freefem_files::digits(head.substr(at, end - at))) return false;
    at = end;
  }
  return true;
}

MeshFile read_freefem(std::string_view text, const std::string& source) {
  using namespace freefem_files;
  TextReader r(text, source);
  const std::int64_t nv = read_count(r, "number of vertices (nv)");
  const std::int64_t nt = read_count(r, "number of triangles (nt)");
  const std::int64_t nbe = read_count(r, "number of boundary edges (nbe)");
  MeshFile f;
  for (std::int64_t i = 0; i < nv; ++i) {
    const std::string what = entry("vertex", i);
    f.mesh.sites.push_back({r.number(what + ": x"), r.number(what + ": y")});
    f.vertex_refs.push_back(read_label(r, what));
  }
  for (std::int64_t i = 0; i < nt; ++i) {
    const std::string what = entry("triangle", i);
    std::array<int, 3> t{};
    for (int& corner : t) corner = read_vertex(r, what + ": vertex", nv);
    f.mesh.triangles.push_back(t);
    f.triangle_refs.push_back(read_label(r, what));
  }
  for (std::int64_t i = 0; i < nbe; ++i) {
    const std::string what = entry("boundary edge", i);
    const int a = read_vertex(r, what + ": vertex", nv);
    const int b = read_vertex(r, what + ": vertex", nv);
    f.mesh.edges.emplace_back(a, b);
    f.edge_refs.push_back(read_label(r, what));
  }
  expect_end(r, "boundary edges", nbe);
  return f;
}

MeshFile read_freefem_file(const std::string& path) { return read_freefem(read_whole_file(path), path); }

// The .msh, and BASE.mtr beside it ("nbv 3") when the mesh has metrics.
std::vector<FileText> write_freefem_file(const MeshFile& m, const std::string& path) {
  require_triangle_mesh(m, "FreeFem .msh");
  std::vector<FileText> files{{path, freefem_files::msh_text(m, path)}};
  if (!m.mesh.metrics.empty())
    files.push_back(write_bamg_metric(m.mesh.metrics, std::filesystem::path(path).replace_extension(".mtr").string()));
  return files;
}

namespace {

// BAMG reads the values as a stream of numbers, so a file whose lines do not hold one vertex each
// is refused only where a value is not what its place in the stream needs, or at the end, often
// lines later. The message then names the first line that does not hold as many values as the
// header declares per vertex: when it is the first line of values and holds the other kind's
// count, the header was most likely meant to declare that kind; otherwise every vertex after
// that line is read shifted. Nothing when every line holds one vertex.
std::string line_hint(std::string_view text, std::int64_t kind) {
  int line = 1, tokens = 0, values = 0;  // values: on this line, after the header's two tokens
  bool first = true;                     // no line of values ended yet
  const auto hint = [&]() -> std::string {
    const std::string held = "line " + std::to_string(line) + " holds " + std::to_string(values) + (values == 1 ? " value" : " values") +
                             ", where the header declares " + std::to_string(kind) + " per vertex";
    if (first && (values == 1 || values == 3))
      return " (" + held + ": should its second number be " + std::to_string(values) + "?)";
    return " (" + held + ": the vertices after it are read shifted)";
  };
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == '\n') {
      if (values > 0 && values != kind) return hint();
      if (values > 0) first = false;
      values = 0;
      ++line;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(text[i])) || (i > 0 && !std::isspace(static_cast<unsigned char>(text[i - 1])))) continue;
    if (++tokens > 2) ++values;  // a token starts here: the header's, or a value
  }
  return "";
}

}  // namespace

std::vector<predicates::Sym2<Rational>> read_bamg_metric(std::string_view text, const std::string& source) {
  using namespace freefem_files;
  TextReader r(text, source);
  const std::int64_t nbv = read_count(r, "number of vertices (nbv)");
  const std::int64_t kind = r.integer("header: values per vertex", INT64_MIN, INT64_MAX);
  if (kind != 1 && kind != 3)
    r.fail("header: " + std::to_string(kind) + " values per vertex, where BAMG has 1 (a size h) or 3 (a11 a21 a22)");
  std::vector<Sym2<Rational>> metrics;
  try {
    for (std::int64_t i = 0; i < nbv; ++i)
      metrics.push_back(kind == 1 ? read_size(r, entry("vertex", i)) : read_tensor(r, entry("vertex", i)));
    expect_end(r, "metrics", nbv);
  } catch (const InputError& e) {
    throw InputError(e.what() + line_hint(text, kind));
  }
  return metrics;
}

std::vector<predicates::Sym2<Rational>> read_bamg_metric_file(const std::string& path) {
  return read_bamg_metric(read_whole_file(path), path);
}

FileText write_bamg_metric(const std::vector<predicates::Sym2<Rational>>& metrics, const std::string& path) {
  std::string s = std::to_string(metrics.size()) + " 3\n";
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string what = path + ": " + freefem_files::entry("metric", static_cast<std::int64_t>(i));
    s += decimal_text(metrics[i].m11, what + ": a11") + " " + decimal_text(metrics[i].m12, what + ": a21") + " " +
         decimal_text(metrics[i].m22, what + ": a22") + "\n";
  }
  return {path, s};
}

}  // namespace anisocert::io
