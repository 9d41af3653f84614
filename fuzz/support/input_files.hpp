#pragma once
// One fuzz input holding several files (a mesh and its metric file, Triangle's .node, .ele and
// .poly), the way GDAL's fuzzers pack an archive into one input: the parts are separated by the
// marker line below (docs/fuzzing.md). Each part is written to a scratch folder of this process
// (in /dev/shm when there is one) as fuzz-input<extension>, since the readers read files.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace anisocert::fuzz {

inline constexpr std::string_view file_marker = "\n--8<-- anisocert fuzz: next file\n";

// The parts of data, split at each marker (at most max_parts: the last part keeps the rest).
std::vector<std::string_view> split_files(const std::uint8_t* data, std::size_t size, std::size_t max_parts);

// The scratch folder's path of fuzz-input<extension>, after writing bytes to it.
std::string write_scratch(std::string_view extension, std::string_view bytes);

// Removes fuzz-input<extension> from the scratch folder, if it is there.
void remove_scratch(std::string_view extension);

// The path fuzz-input<extension> would have (nothing written).
std::string scratch_path(std::string_view extension);

}  // namespace anisocert::fuzz
