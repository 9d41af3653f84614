#pragma once
// The rules of LU §4.1 in dimension 3 (issue 40), in rules.hpp's priority order and with its names:
//   1 encroachment of a subsegment, then of a subfacet (refiners/common/boundary3.hpp);
//   2 distortion: a tetrahedron whose vertices' metrics differ by γ ≥ γ₀ (predicates/
//     distortion.hpp, exact), or differ so from the field at its M_v-circumcentre when Ω holds it
//     (LU's total distortion over the circumball, estimated from below);
//   3 radius-edge ratio > ρ₀ in M_v (LU Definition 3.10);
//   4 size: M_v-circumradius > `size`;
//   5 inconsistency: a tetrahedron of S_v missing from the star of one of its other vertices (LU
//     Definition 3.3); of those, the one with the largest M_v-circumradius (a choice; `anisocert
//     refine --domain cube --field ugawg-linear`: 33,579 vertices instead of the first found's
//     36,529 at h0 = 0.02, 4,906 instead of 4,871 at h0 = 0.05).
// LU's own rule (4), cosphericity, is not a rule here: its γ₀-cospherical configurations are what
// Pick_valid avoids creating (pick_valid3.hpp), and the certifier measures every face pair's
// (quasi_cosphericity in oracle/certify).
#include "fields/metric_field.hpp"
#include "refiners/star/parameters.hpp"
#include "refiners/star/rules.hpp"
#include "refiners/star/star_set3.hpp"

namespace anisocert::refiners::star {

// The tetrahedron (v, t[0], t[1], t[2]) of S_v to refine and the rule that asks for it.
struct Action3 {
  Rule rule = Rule::none;
  std::array<int, 3> t{};
};

Action3 first_rule3(int v, const StarSet3& stars, const common::Sites3& sites, const common::Domain3& domain, const RefineParameters& p);

}  // namespace anisocert::refiners::star
