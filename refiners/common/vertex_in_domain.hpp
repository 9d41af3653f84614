#pragma once
// Whether a certified point (a Voronoi vertex, certified_point.hpp) lies in the closed domain Ω:
// its box when that decides (Domain::contains(Box)), else the crossing number of a ray to the right
// with exact signs at the point. Nothing when a sign is undecided (the point on an edge's line or a
// corner's height, and irrational there).
#include "refiners/common/certified_point.hpp"
#include "refiners/common/domain.hpp"

#include <optional>

namespace anisocert::refiners::common {

std::optional<bool> in_closed_domain(const Domain& domain, const CertifiedPoint& p);

}  // namespace anisocert::refiners::common
