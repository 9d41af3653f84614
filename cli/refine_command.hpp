#pragma once
// Shared by `anisocert refine` and `anisocert demo`: a refiner's mesh in the one mesh shape.
#include "io/mesh_output.hpp"
#include "refiners/registry.hpp"

#include <string>

namespace anisocert::cli {

// The refiner's report lines as text, one per line.
std::string report_text(const refiners::Run& run);

}  // namespace anisocert::cli
