// VTK XML unstructured grids .vtu (docs/fuzzing.md § Parsers): ASCII, base64 and appended raw or
// base64 data, zlib blocks, both header types and byte orders, the point array "metric"; the
// properties of fuzz/support/mesh_reader_check.hpp. Limit: 64 KiB (-max_len in fuzz/campaign).
#include "fuzz/support/mesh_reader_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  static const anisocert::fuzz::MeshReaderCase vtu{"vtu", {".vtu"}, "", false};
  anisocert::fuzz::check_mesh_reader(vtu, data, size);
  return 0;
}
