#pragma once
// The BWY refiner's line in the registry (refiners/registry.hpp): its parameters and its report.
#include "refiners/registry.hpp"

namespace anisocert::refiners::bwy {

RefinerEntry entry();

}  // namespace anisocert::refiners::bwy
