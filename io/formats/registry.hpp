#pragma once
// The mesh and metric formats, one entry each (a format is added here and in its own file):
// chosen by the file's extension, or by name with --format. Two formats share ".msh" (Gmsh and
// FreeFem); the first token tells them apart.
#include "io/formats/mesh_file.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace anisocert::io {

// What a user may allow a reader beyond the format's strict reading.
struct ReadOptions {
  bool planar_3d = false;   // a 3D file (Medit Dimension 3) whose every z is 0 is read as 2D
  // A 3D file with triangles and no tetrahedra (a closed surface: `refine --domain`, issue 40) is
  // read into mesh3 (dimension 3, its triangles in mesh3.triangles); Medit and Gmsh only.
  bool surface = false;
};

struct MeshFormat {
  std::string name;                      // the --format value
  std::string summary;                   // one line for --help
  std::vector<std::string> extensions;   // ".mesh", ".meshb", ...
  // Whether a file with one of the extensions is in this format, from its first bytes (nullptr:
  // always).
  bool (*recognizes)(std::string_view head) = nullptr;
  MeshFile (*read)(const std::string& path, const ReadOptions& o) = nullptr;
  // The files of m at path (several for the formats that split a mesh, e.g. Triangle's .node and
  // .ele, or Medit's .mesh and .sol when there are metrics).
  std::vector<FileText> (*write)(const MeshFile& m, const std::string& path) = nullptr;
  // Whether its files hold the metrics (Triangle's hold none: they are given with --metric).
  bool holds_metrics = true;
};

struct MetricFormat {
  std::string name, summary;
  std::vector<std::string> extensions;
  bool (*recognizes)(std::string_view head) = nullptr;
  std::vector<predicates::Sym2<Rational>> (*read)(const std::string& path) = nullptr;
  FileText (*write)(const std::vector<predicates::Sym2<Rational>>& metrics, const std::string& path) = nullptr;
  // The 3×3 metrics of a tetrahedral mesh (nullptr: the format holds 2D metrics only).
  std::vector<predicates::Sym3<Rational>> (*read3)(const std::string& path) = nullptr;
  FileText (*write3)(const std::vector<predicates::Sym3<Rational>>& metrics, const std::string& path) = nullptr;
};

const std::vector<MeshFormat>& mesh_formats();
const std::vector<MetricFormat>& metric_formats();
// Whether some metric format has the extension of path.
bool has_metric_extension(const std::string& path);
std::vector<std::string> mesh_format_names();

// The format of path: by `forced` when not empty (its name), else by extension (and content for
// ".msh"). Throws InputError naming the file and the formats it could be.
const MeshFormat& mesh_format_of(const std::string& path, const std::string& forced = "");
const MetricFormat& metric_format_of(const std::string& path, const std::string& forced = "");

// The format to write path in: `forced` when not empty, else the first format with its extension
// (Gmsh for ".msh"). Throws InputError naming the path.
const MeshFormat& mesh_format_to_write(const std::string& path, const std::string& forced = "");

// Read a mesh file and its metrics in one call: from metric_path when given, else the file's own
// (Gmsh $NodeData, JSON), else for a Medit BASE.mesh (.meshb) the BASE.sol (.solb) beside it when
// there is one (MMG's convention). MeshFile::metric_source says which.
MeshFile read_mesh_file(const std::string& path, const std::string& format = "", const ReadOptions& o = {},
                        const std::string& metric_path = "", const std::string& metric_format = "");

}  // namespace anisocert::io
