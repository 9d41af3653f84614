#pragma once
// One step of gift wrapping around a point p in Del_M (LU Definition 2.1): from a Delaunay
// neighbour u of p, the next one counter-clockwise (or clockwise) among the candidates is the one
// on that side of pu whose M-circle through p and u holds no other candidate; exact orientation
// and in-circle tests, ties (cocircular candidates) broken towards the nearer angle.
#include "predicates/point.hpp"

#include <vector>

namespace anisocert::refiners::star {

// The next Delaunay neighbour of p after u among `cand` (indices into `points`), or −1 if none.
int next_delaunay_neighbour(const predicates::Point2<double>& p, const predicates::Sym2<double>& M, int u,
                            const std::vector<int>& cand, bool counter_clockwise,
                            const std::vector<predicates::Point2<double>>& points);

}  // namespace anisocert::refiners::star
