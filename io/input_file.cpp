#include "io/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace anisocert::io {

std::ifstream open_input(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot open: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  return in;
}

}  // namespace anisocert::io
