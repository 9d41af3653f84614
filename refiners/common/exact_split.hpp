#pragma once
// Boundary subsegments are split at their midpoints (LU Rule 1); for the mesh to be a valid
// triangulation of Ω each new vertex must lie exactly on ∂Ω, so the midpoint must be a double.
// Doubles far apart in magnitude or with many significant bits have no double midpoint: the
// edge from (1, 0.4) to (0.4, 1) (0.4 as a double, an odd multiple of 2⁻⁵⁴) has no double point
// at all with y ∈ [0.5, 1). Domains are therefore checked before refinement, and each split is
// checked again.
#include "predicates/point.hpp"

#include <optional>

namespace anisocert::refiners::common {

// The refiner accepts a domain whose every edge can be halved exactly this many times (2⁻³⁰ of
// the edge's length: far below any boundary refinement that ends).
constexpr int min_halvings = 30;

// How many times segment ab can be halved with every point a double: a lower bound from the
// coordinates' common binary grid and magnitude (a coordinate equal at both ends never limits).
int exact_halvings(const predicates::Point2<double>& a, const predicates::Point2<double>& b);
// How many times ab can be split with a double exactly on it inside every piece: exact_halvings,
// or on an axis-parallel segment, where every double between the ends lies on it, the halvings
// that leave each piece two units in the last place long if that is more (a mesh's boundary
// vertices, whose coordinates have all their bits: `refine --from`). Split points are then taken
// among all its doubles when the grid has none (segment_cells.hpp). What Domain checks.
int split_halvings(const predicates::Point2<double>& a, const predicates::Point2<double>& b);

// The midpoint of ab when it is a double (exactly on ab), else nothing.
std::optional<predicates::Point2<double>> exact_midpoint(const predicates::Point2<double>& a,
                                                         const predicates::Point2<double>& b);
// The same in space (issue 40: a boundary facet's edge is halved; the midpoint of two points of a
// plane lies on it, so a double midpoint lies exactly on every input facet holding both ends).
int exact_halvings(const predicates::Point3<double>& a, const predicates::Point3<double>& b);
std::optional<predicates::Point3<double>> exact_midpoint(const predicates::Point3<double>& a,
                                                         const predicates::Point3<double>& b);

}  // namespace anisocert::refiners::common
