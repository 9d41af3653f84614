// FreeFem++ .msh and, after the file marker, a BAMG .mtr (docs/fuzzing.md § Parsers); the
// properties of fuzz/support/mesh_reader_check.hpp. Limit: 64 KiB (-max_len in fuzz/campaign).
#include "fuzz/support/mesh_reader_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return -1;
  static const anisocert::fuzz::MeshReaderCase freefem{"freefem", {".msh"}, ".mtr", false};
  anisocert::fuzz::check_mesh_reader(freefem, data, size);
  return 0;
}
