#pragma once
// The rules of LU §4.1 as the star refiner implements them, in priority order (a lower number
// first): the rule numbers of the trace and the names of the report come from here.
//   1 encroachment: a boundary subsegment with a site inside its diametral ellipse (in the site's
//     or the endpoints' metric; LU Definition 3.16) is split at its midpoint (refiners/common);
//   2 distortion: a triangle whose vertices' metrics differ by τ ≥ γ₀, or differ so from the field
//     at the circumcentre (LU's total distortion over the circumball, estimated from below);
//   3 radius-edge ratio > ρ₀ in M_v;
//   4 size: circumradius in M_v > `size` (so that the mesh fits the field);
//   5 inconsistency: a triangle of S_v missing from the star of one of its other vertices (LU
//     Definition 3.3 at the level of triangles).
#include "fields/metric_field.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/star/parameters.hpp"
#include "refiners/star/star_set.hpp"

#include <array>

namespace anisocert::refiners::star {

enum class Rule { none = 0, encroachment = 1, distortion = 2, radius_edge = 3, size = 4, inconsistency = 5 };
inline constexpr std::array<Rule, 5> rules_by_priority{Rule::encroachment, Rule::distortion, Rule::radius_edge, Rule::size,
                                                       Rule::inconsistency};
const char* rule_name(Rule rule);

// The triangle (v, a, b) of S_v to refine and the rule that asks for it.
struct Action {
  Rule rule = Rule::none;
  int a = -1, b = -1;
};

// The first rule (2–5) that fires on a triangle of v's star, and that triangle; Rule::none when
// the star is done.
Action first_rule(int v, const StarSet& stars, const common::Sites& sites, const common::Domain& domain,
                  const RefineParameters& p);

}  // namespace anisocert::refiners::star
