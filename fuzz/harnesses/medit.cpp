// Medit ASCII (docs/fuzzing.md § Parsers): a .mesh and, after the file marker, its .sol; the
// properties of fuzz/support/mesh_reader_check.hpp. Dimension 3 files are read with --planar-3d.
// Limit: 64 KiB (-max_len in fuzz/campaign).
#include "fuzz/support/mesh_reader_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  static const anisocert::fuzz::MeshReaderCase medit{"medit", {".mesh"}, ".sol", true};
  anisocert::fuzz::check_mesh_reader(medit, data, size);
  return 0;
}
