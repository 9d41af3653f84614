#include "fuzz/support/input_files.hpp"

#include "fuzz/support/finding.hpp"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace anisocert::fuzz {
namespace {

const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base = std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path();
    std::filesystem::path f = base / ("anisocert-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  return folder;
}

// The folder goes when the process ends normally (a crash leaves it for inspection).
struct RemoveAtExit {
  ~RemoveAtExit() {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_folder(), ignored);
  }
};

}  // namespace

std::vector<std::string_view> split_files(const std::uint8_t* data, std::size_t size, std::size_t max_parts) {
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < max_parts) {
    const std::size_t k = rest.find(file_marker);
    if (k == std::string_view::npos) break;
    parts.push_back(rest.substr(0, k));
    rest.remove_prefix(k + file_marker.size());
  }
  parts.push_back(rest);
  return parts;
}

std::string scratch_path(std::string_view extension) {
  // The folder first: statics are destroyed in the reverse order of their construction, so the
  // remover then runs while the folder's path still exists (made the other way round, it removed
  // a destroyed path, and every replay left its folder behind).
  const std::filesystem::path& folder = scratch_folder();
  static RemoveAtExit remover;
  return (folder / ("fuzz-input" + std::string(extension))).string();
}

std::string write_scratch(std::string_view extension, std::string_view bytes) {
  const std::string path = scratch_path(extension);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) finding("cannot write the scratch file " + path);
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !written) finding("cannot write the scratch file " + path);
  return path;
}

void remove_scratch(std::string_view extension) {
  std::error_code ignored;
  std::filesystem::remove(scratch_path(extension), ignored);
}

}  // namespace anisocert::fuzz
