#pragma once
// The Labelle–Shewchuk refiner's line in the registry (refiners/registry.hpp): `anisocert refine --algo ls`.
#include "refiners/registry.hpp"

namespace anisocert::refiners::ls {

RefinerEntry entry();

}  // namespace anisocert::refiners::ls
