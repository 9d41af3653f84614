#pragma once
// The Labelle–Shewchuk refiner's parameters (LS §9): θ_bound and the size bound, with the budgets
// every run has.
#include "refiners/common/result.hpp"

namespace anisocert::refiners::ls {

struct LsParameters : common::Budget {
  double theta_bound = 20;  // degrees; LS Theorem 11 needs θ_bound < arcsin(1/(2√2)) ≈ 20.7°
  double size = 1;          // largest circumradius in the metric; 0: no size rule (LS Theorem 11's setting)
  // LS §9's variation: the diagram from M′_p = det(M_p)^(−1/2) M_p (fields/normalized.hpp), sizes
  // judged with M_p. The sites' metrics, and the mesh's, are then M′.
  bool normalized_metric = false;
  // Poor angle and too large insert at the off-centre of the vertex's shortest edge whose lengths
  // are nearest unit (common::VoronoiRefinement::attack_off_centre); with a field that varies (LS
  // with one metric runs Del_M, ls_refiner.cpp, and refuses it).
  bool off_centres = false;
  bool filters = true;      // false: every decision the filters take is taken in rationals (tests compare the two)
};

}  // namespace anisocert::refiners::ls
