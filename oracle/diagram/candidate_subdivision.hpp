#pragma once
// Certified subdivision: which sites can own a point of a box (LS Definition 1: p belongs to the
// cell of v when d_v(p) ≤ d_u(p) for every site u).
//
// A box B keeps site u unless some site t is strictly closer than u at every point of B, which
// is certified by   min_B Q_u > max_B Q_t   on outward-rounded interval bounds of the centred
// form Q(c + h) = Q(c) + 2(c − u)ᵀMh + hᵀMh. A dropped site therefore owns no point of B, so
// every point of the diagram in B has all of its owners among B's candidates. The boxes are
// refined while they have more than three candidates (up to a depth limit; past a budget of boxes,
// the input is declined with std::domain_error, by name), and the leaves cover
// the domain's bounding box. Hence (this is the completeness argument of docs/oracle.md):
//  - every Voronoi vertex lies in a leaf whose candidates include all of its owners, so each of
//    its owner triples is among `triples`;
//  - every point of an arc lies in a leaf whose candidates include both owners, so each pair of
//    sites whose cells share a point is among `pairs`;
//  - every nearest site of a point is a candidate of each leaf containing it, so the nearest sites
//    are found among the candidates of the leaves meeting a box around the point (`sites_near`).
// The box arithmetic only decides what is kept, never an answer: a loose bound keeps more.
#include "oracle/diagram/input.hpp"
#include "numbers/filter_interval.hpp"
#include <array>
#include <cstdint>
#include <vector>

namespace anisocert::oracle {

struct BoxBounds {
  double x_lo, x_hi, y_lo, y_hi;
};

struct CandidateSets {
  std::vector<std::array<int, 3>> triples;  // sorted, each once
  std::vector<BoxBounds> triple_region;     // the bounding box of the leaves of each triple
  std::vector<std::pair<int, int>> pairs;   // sorted, each once
  std::vector<BoxBounds> pair_region;       // the bounding box of the leaves of each pair
  std::size_t boxes = 0, leaves = 0;
  int max_depth_reached = 0;

  // The candidates of the leaves meeting [x] × [y], sorted: they hold every nearest site of each
  // point of the box that lies in the root box (Ω's bounding box), but not necessarily of the
  // points outside it, which are outside Ω. Every site when the box misses the root box.
  std::vector<int> sites_near(const FilterInterval& x, const FilterInterval& y) const;

  // The subdivision, in the input's coordinates scaled by 2^scale_exponent (the regions above
  // are in the input's coordinates): cells[0] is the root; a split cell's four children are
  // consecutive.
  int scale_exponent = 0;
  struct Cell {
    BoxBounds box;
    int first_child = -1;
    int leaf = -1;  // index into leaf_sites for a leaf
  };
  std::vector<Cell> cells;
  std::vector<std::vector<int>> leaf_sites;
  int sites = 0;
};

CandidateSets candidate_sets(const Mesh<Rational>& in, int max_depth = 40);

}  // namespace anisocert::oracle
