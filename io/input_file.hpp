#pragma once
// Opening an input file for reading, once for every reader: a path that names a directory or
// cannot be opened is bad input (InputError, exit 2), named with the system's reason, not a
// stream error found half-way through a read.
#include "io/input_error.hpp"

#include <fstream>
#include <string>

namespace anisocert::io {

std::ifstream open_input(const std::string& path);

}  // namespace anisocert::io
