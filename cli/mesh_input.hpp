#pragma once
// A mesh file and its metrics as the commands that check a mesh take them (`certify`, `dual`):
// the file in any format of io/formats/registry.hpp, its metric from the file itself, from
// --metric FILE or from --field (io/field_source.hpp), with the same options and messages.
#include "io/formats/mesh_file.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace anisocert::cli {

struct MeshInput {
  std::string path, format, metric, metric_format, field;
  std::vector<std::string> params;
  bool planar_3d = false;
};

// The positional `mesh` and --format, --metric, --metric-format, --field, --param, --planar-3d.
void add_mesh_input_options(CLI::App* command, MeshInput& in);

// The mesh with its metrics (metric_source says from where); UsageError for bad input.
io::MeshFile read_mesh_input(const MeshInput& in);

}  // namespace anisocert::cli
