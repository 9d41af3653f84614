#pragma once
// The BWY refiner's parameters (BWY §3.2.2, §4.2): the shape bound B, the distortion coefficient G
// of §4.2's conditions, and LS §9's size bound, with the budgets every run has.
#include "refiners/common/result.hpp"

namespace anisocert::refiners::bwy {

struct BwyParameters : common::Budget {
  double shape_bound = 1.5;  // B: a Voronoi vertex with r(v)/δ(t_v) > B is badly shaped
  // G: the distortion §4.2's conditions are decided for (the refiner does not use it); 0: the
  // largest G for which Lemma 2's condition holds with B, from theory/ (rounded down).
  double distortion = 0;
  double size = 1;  // largest radius r(v) in the metric; 0: no size rule
  // Rules 3 and 6 insert at the off-centre of the Voronoi vertex's shortest edge whose lengths are
  // nearest unit (VoronoiRefinement::attack_off_centre), not at the vertex.
  bool off_centres = false;
  bool filters = true;  // false: the segment tests' decisions in rationals
};

}  // namespace anisocert::refiners::bwy
