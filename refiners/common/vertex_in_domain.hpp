#pragma once
// Whether a certified point (a Voronoi vertex, certified_point.hpp) lies in the closed domain Ω:
// its box when that decides (Domain::contains(Box)), else the crossing number of a ray to the right,
// or when that is undecided to the left, with exact signs at the point (of the edges the ray can
// meet). Nothing when a sign is undecided both ways (the point on an edge's line or a corner's
// height on both sides, and irrational there).
#include "refiners/common/certified_point.hpp"
#include "refiners/common/domain.hpp"

#include <optional>

namespace anisocert::refiners::common {

std::optional<bool> in_closed_domain(const Domain& domain, const CertifiedPoint& p);

}  // namespace anisocert::refiners::common
