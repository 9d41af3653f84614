// Gmsh .msh 4.1 (ASCII and binary) and 2.2 (docs/fuzzing.md § Parsers), metrics from $NodeData;
// the properties of fuzz/support/mesh_reader_check.hpp. Limit: 64 KiB (-max_len in fuzz/campaign).
#include "fuzz/support/mesh_reader_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  static const anisocert::fuzz::MeshReaderCase gmsh{"gmsh", {".msh"}, "", false};
  anisocert::fuzz::check_mesh_reader(gmsh, data, size);
  return 0;
}
