#pragma once
// The star refiner's line in the registry (refiners/registry.hpp): `anisocert refine --algo star`.
#include "refiners/registry.hpp"

namespace anisocert::refiners::star {

RefinerEntry entry();

}  // namespace anisocert::refiners::star
