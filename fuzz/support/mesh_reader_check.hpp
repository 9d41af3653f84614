#pragma once
// The property every mesh-format harness checks (docs/fuzzing.md § Parsers). For one input packing
// a mesh file and the files that go with it:
//   - reading gives a mesh or an InputError whose message is one short line naming the file;
//     anything else (another exception, a crash, a sanitizer report, a timeout, memory beyond
//     -rss_limit_mb) is a finding;
//   - a mesh read is written back by the format's own writer (or refused by an InputError: a number
//     the format cannot hold) and read again: sites, metrics, triangles and edges come back exactly;
//   - a small mesh read is certified (validity, and local uniformity with its metrics) without
//     an exception other than std::invalid_argument, the certifier's documented refusal.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace anisocert::fuzz {

struct MeshReaderCase {
  std::string format;                        // the registry's mesh format name
  std::vector<std::string> mesh_extensions;  // the files of the mesh, the one to open first
  std::string metric_extension;              // a separate metric file's extension ("" for none)
  bool planar_3d = false;                    // ReadOptions::planar_3d
};

// Splits data into the case's files (mesh files in order, then the metric file) and checks them.
void check_mesh_reader(const MeshReaderCase& c, const std::uint8_t* data, std::size_t size);

}  // namespace anisocert::fuzz
