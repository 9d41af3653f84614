#pragma once
// A refiner's report (refiners/registry.hpp: the lines its entry wrote) as text.
#include "refiners/registry.hpp"

#include <string>

namespace anisocert::cli {

std::string report_text(const refiners::Run& run);

}  // namespace anisocert::cli
