#pragma once
// Gift wrapping around a point p in Del_M (LU Definition 2.1). It starts at p's M-nearest
// candidate, a Delaunay neighbour (the M-circle on the segment to it as diameter holds no other
// candidate), decided exactly: chosen by doubles alone, a metric of condition 2⁴⁰ made it a
// candidate that is none, and the fan wound three times around p (tests/refiner_star_test.cpp).
// From a Delaunay neighbour u of p, the next one counter-clockwise (or clockwise) among the
// candidates is the one on that side of pu whose M-circle through p and u holds no other
// candidate; exact orientation and in-circle tests, ties (cocircular candidates) broken towards
// the nearer angle.
#include "predicates/point.hpp"

#include <vector>

namespace anisocert::refiners::star {

// The M-nearest of `cand` (indices into `points`, not empty) to p, exactly; of equally near ones,
// the first listed. Doubles with an error bound keep the few that may be nearest, and the exact
// comparison of lengths decides among them.
int nearest_candidate(const predicates::Point2<double>& p, const predicates::Sym2<double>& M, const std::vector<int>& cand,
                      const std::vector<predicates::Point2<double>>& points);

// The next Delaunay neighbour of p after u among `cand` (indices into `points`), or −1 if none.
int next_delaunay_neighbour(const predicates::Point2<double>& p, const predicates::Sym2<double>& M, int u,
                            const std::vector<int>& cand, bool counter_clockwise,
                            const std::vector<predicates::Point2<double>>& points);

}  // namespace anisocert::refiners::star
