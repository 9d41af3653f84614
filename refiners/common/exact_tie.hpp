#pragma once
// LS §7's Voronoi vertices of degree four or more among sites that share one metric, decided
// exactly, for the refinement that keeps the true diagram (ls_varying.hpp). Grid corners in a
// region of one metric lie on common ellipses of it, and there the diagram's subdivision
// (vertex_subdivision.hpp) leaves the leaves around the vertex unresolved. When every candidate of
// such a leaf has one metric M and all lie on one ellipse of M about a point c, no other site is
// as near anywhere in the leaf, and the candidates' diagram is the affine image of the Euclidean
// diagram of cocircular points: its only vertex is c, of degree k. The leaf holds that vertex when
// c is in the closed leaf, and none otherwise.
//
// LS §9 judges the triangles dual to a vertex; the dual of a vertex of degree k is a k-gon, and
// every triangulation of it is a dual of D (LS §7). The vertex is a violator when no fan of the
// k-gon has all its angles at least θ_bound in M (for four sites: neither diagonal), and the mesh
// gets a fan that has. In M fans are enough: every triangulation of cocircular points has the same
// smallest angle (half the smallest arc). In the field's metric at c, also judged, a triangulation
// that is no fan might pass where no fan does (k ≥ 6); then a site is inserted that need not be,
// which is safe.
#include "numbers/rational.hpp"
#include "refiners/common/distance_function.hpp"
#include "refiners/common/domain.hpp"

#include <array>
#include <optional>
#include <vector>

namespace anisocert::refiners::common {

struct ExactTie {
  std::vector<int> sites;                  // counter-clockwise around c
  predicates::Point2<Rational> c;          // at one distance from each, in their metric
};

// The tie the candidates (ids into `sites`) make, or nothing when there are fewer than four, their
// metrics differ, or they are not on one ellipse of their metric.
std::optional<ExactTie> exact_tie(const std::vector<common::MetricSite>& sites, const std::vector<int>& candidates);

// Whether c lies in the closed box b, exactly.
bool in_closed_box(const predicates::Point2<Rational>& c, const common::Box& b);

// The fan of the tie's polygon from its site `apex` (an index into tie.sites): counter-clockwise
// triangles, the polygon being convex (its sites lie on an ellipse about c).
std::vector<std::array<int, 3>> fan(const ExactTie& tie, std::size_t apex);

// The first fan whose every angle is at least arcsin √s2 in each of `metrics`, decided exactly;
// nothing when no fan has.
std::optional<std::vector<std::array<int, 3>>> good_fan(const ExactTie& tie, const std::vector<common::MetricSite>& sites,
                                                        const std::vector<predicates::Sym2<double>>& metrics, double s2);

}  // namespace anisocert::refiners::common
