// Medit binary (docs/fuzzing.md § Parsers): a .meshb and, after the file marker, its .solb (either
// byte order, versions 1-4); the properties of fuzz/support/mesh_reader_check.hpp.
// Limit: 64 KiB (-max_len in fuzz/campaign).
#include "fuzz/support/mesh_reader_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  static const anisocert::fuzz::MeshReaderCase medit{"medit", {".meshb"}, ".solb", true};
  anisocert::fuzz::check_mesh_reader(medit, data, size);
  return 0;
}
