#include "io/formats/registry.hpp"

#include "io/formats/freefem.hpp"
#include "io/formats/gmsh.hpp"
#include "io/formats/gmsh_view.hpp"
#include "io/formats/medit.hpp"
#include "io/formats/vtu.hpp"
#include "io/formats/text_reader.hpp"
#include "io/formats/triangle.hpp"
#include "io/input_file.hpp"
#include "io/mesh_json.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace anisocert::io {
namespace {

MeshFile read_json(const std::string& path, const ReadOptions&) {
  MeshFile f;
  f.mesh = read_triangle_mesh_file(path);
  return f;
}

std::vector<FileText> write_json(const MeshFile& m, const std::string& path) {
  require_triangle_mesh(m, "anisocert's JSON");
  return {{path, mesh_json(m.mesh)}};
}

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

std::string head_of(const std::string& path) {
  std::ifstream in = open_input(path);
  std::string head(256, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

template <class Format>
const Format& format_of(const std::vector<Format>& formats, const std::string& path, const std::string& forced,
                        const char* kind, const char* option) {
  std::string names;
  for (const Format& f : formats) names += (names.empty() ? "" : ", ") + f.name;
  if (!forced.empty()) {
    for (const Format& f : formats)
      if (f.name == forced) return f;
    throw InputError(std::string(option) + ": unknown " + kind + " format " + quoted_excerpt(forced) + " (" + names + ")");
  }
  const std::string ext = extension_of(path);
  std::vector<const Format*> by_extension;
  for (const Format& f : formats)
    if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) by_extension.push_back(&f);
  if (by_extension.empty())
    throw InputError(path + ": no " + std::string(kind) + " format has the extension \"" + ext + "\"; name one with " +
                     option + " (" + names + ")");
  if (by_extension.size() == 1) return *by_extension.front();
  const std::string head = head_of(path);
  for (const Format* f : by_extension)
    if (f->recognizes && f->recognizes(head)) return *f;
  throw InputError(path + ": the first bytes are not those of any " + std::string(kind) + " format with the extension \"" +
                   ext + "\"; name one with " + option + " (" + names + ")");
}

}  // namespace

const std::vector<MeshFormat>& mesh_formats() {
  static const std::vector<MeshFormat> formats{
      {"json", "anisocert's own JSON (sites, metrics, domain, segments, triangles)", {".json"}, nullptr, read_json, write_json},
      {"medit", "Medit .mesh/.meshb (MMG, libMeshb), versions 1-4; metrics in .sol/.solb", {".mesh", ".meshb"}, nullptr,
       [](const std::string& p, const ReadOptions& o) { return read_medit_file(p, {o.planar_3d, o.surface}); }, write_medit_file},
      {"gmsh", "Gmsh .msh 4.1 (ASCII, binary) or 2.2 (ASCII); metrics in $NodeData", {".msh"}, looks_like_gmsh,
       [](const std::string& p, const ReadOptions& o) { return read_gmsh_file(p, o.surface); }, write_gmsh_file},
      {"freefem", "FreeFem++ .msh (nv nt nbe); metrics in BAMG .mtr", {".msh"}, looks_like_freefem,
       [](const std::string& p, const ReadOptions&) { return read_freefem_file(p); }, write_freefem_file},
      {"triangle", "Triangle .node/.ele/.poly (boundary markers, holes); TetGen .node/.ele/.face (3D)", {".node", ".ele", ".poly", ".face"}, nullptr,
       [](const std::string& p, const ReadOptions&) { return read_triangle_files(p); }, write_triangle_files, false},
      {"vtu", "VTK XML unstructured grid .vtu (ASCII, base64, zlib, appended; Omega_h, Pragmatic, ParaView); metrics in the point array \"metric\"",
       {".vtu"}, nullptr, [](const std::string& p, const ReadOptions&) { return read_vtu_file(p); }, write_vtu_file},
      {"gmsh-view", "Gmsh list-based tensor view .pos, a background metric for Gmsh's BAMG (written only)", {".pos"}, nullptr,
       nullptr, write_gmsh_view},
  };
  return formats;
}

const std::vector<MetricFormat>& metric_formats() {
  static const std::vector<MetricFormat> formats{
      {"medit", "Medit .sol/.solb: SolAtVertices, type 1 (size) or 3 (tensor)", {".sol", ".solb"}, nullptr,
       read_medit_sol_file, write_medit_sol, read_medit_sol3_file, write_medit_sol3},
      {"bamg", "BAMG .mtr: nbv 1 (sizes) or nbv 3 (a11 a21 a22)", {".mtr"}, nullptr, read_bamg_metric_file,
       write_bamg_metric},
  };
  return formats;
}

std::vector<std::string> mesh_format_names() {
  std::vector<std::string> n;
  for (const MeshFormat& f : mesh_formats()) n.push_back(f.name);
  return n;
}

const MeshFormat& mesh_format_of(const std::string& path, const std::string& forced) {
  return format_of(mesh_formats(), path, forced, "mesh", "--format");
}

bool has_metric_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  return std::any_of(metric_formats().begin(), metric_formats().end(),
                     [&ext](const MetricFormat& f) { return std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end(); });
}

const MetricFormat& metric_format_of(const std::string& path, const std::string& forced) {
  return format_of(metric_formats(), path, forced, "metric", "--metric-format");
}

const MeshFormat& mesh_format_to_write(const std::string& path, const std::string& forced) {
  if (!forced.empty()) return format_of(mesh_formats(), path, forced, "mesh", "--output-format");
  const std::string ext = extension_of(path);
  for (const MeshFormat& f : mesh_formats())
    if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) return f;
  std::string names;
  for (const MeshFormat& f : mesh_formats()) names += (names.empty() ? "" : ", ") + f.name;
  throw InputError(path + ": no mesh format has the extension \"" + ext + "\" (" + names + ")");
}

MeshFile read_mesh_file(const std::string& path, const std::string& format, const ReadOptions& o,
                        const std::string& metric_path, const std::string& metric_format) {
  const MeshFormat& mf = mesh_format_of(path, format);
  if (!mf.read) throw InputError(path + ": anisocert writes " + mf.name + " files but does not read them");
  MeshFile f = mf.read(path, o);
  const bool three = f.dimension == 3;
  const bool has_metrics = three ? !f.mesh3.metrics.empty() : !f.mesh.metrics.empty();
  if (has_metrics) f.metric_source = path;
  std::string metrics = metric_path;
  // MMG's convention: BASE.mesh's metric is BASE.sol (BASE.meshb's, BASE.solb), read when present.
  if (metrics.empty() && !has_metrics && mf.name == "medit") {
    const std::string beside = std::filesystem::path(path).replace_extension(extension_of(path) == ".meshb" ? ".solb" : ".sol").string();
    if (std::ifstream(beside).good()) metrics = beside;
  }
  if (metrics.empty()) return f;
  const MetricFormat& m = metric_format_of(metrics, metric_format);
  if (!three) {
    attach_metrics(f, m.read(metrics), metrics);
  } else if (m.read3) {
    attach_metrics(f, m.read3(metrics), metrics);
  } else {
    throw InputError(metrics + ": " + m.name + " metric files hold 2D metrics, and " + path +
                     " is a tetrahedral mesh (3D metrics: a Medit .sol of Dimension 3)");
  }
  return f;
}

}  // namespace anisocert::io
