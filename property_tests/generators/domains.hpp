#pragma once
// RapidCheck generators of refiner domains: random star-shaped polygons on the 1/64 grid, so that
// every edge can be split exactly many times (refiners/common/exact_split.hpp).
#include "predicates/point.hpp"

#include <utility>
#include <vector>

namespace anisocert::gen {

// Star-shaped around the origin: 5 to 9 vertices at jittered angles and radii, convex, or (reflex)
// 8 to 9 with one vertex pushed in to radius 0.6, a reflex corner (checked). With obtuse_corners,
// discarded unless every convex corner is obtuse, decided exactly on the grid
// ((prev − v)·(next − v) < 0): LU Lemma 4.1 for near-isotropic metrics, and LS Theorem 11's
// separation for θ_bound near its limit. (About 1 in 20 convex and 1 in 7 non-convex draws are
// then discarded.)
std::vector<predicates::Point2<double>> random_domain(bool reflex, bool obtuse_corners = true);

// A comb on the 1/32 grid: a base of height 1/8 with 1 to 4 rectangular teeth (widths and the gaps
// between them 1/32 to 1/8, heights 1/8 to 1/2), so that non-adjacent edges come close (narrow
// slots) while every corner is a right angle, also in any diagonal metric.
std::vector<predicates::Point2<double>> random_comb();

// The rest of a random PSLG for a random_domain of n corners (LS §9's input, refiners/common/
// domain.hpp): none (half the draws), or one to three points on the 1/32 grid in [−¼, ¼]² (inside
// every random_domain) and interior segments between consecutive ones, the first two always
// joined (vertex indices: the n corners, then the points). Not checked here: a draw with two points at one place, or a point on
// the other segment, is the test's to drop (Domain refuses it by name).
struct PslgInterior {
  std::vector<predicates::Point2<double>> points;
  std::vector<std::pair<int, int>> segments;
};
PslgInterior random_pslg_interior(std::size_t n);

}  // namespace anisocert::gen
