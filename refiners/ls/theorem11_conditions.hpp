#pragma once
// LS Theorem 11's conditions on a run, decided by theory/ and the exact angle predicate:
// θ_bound < arcsin(1/(2√2)), and at every corner of Ω the two adjoining segments separated by at
// least 2 arcsin(γ²/2) in the corner's metric, γ = γ(θ_bound) the root > 1 of
// γ⁸ + 2γ⁴√(γ²+1) sin θ_bound − γ⁴ − 1. (bdr_min(γ) > 0, the field's condition, is not decided
// here.) Like the star refiner's LU Lemma 4.1 line, this says where the termination guarantee
// holds, not what the run did.
#include "refiners/common/domain.hpp"

#include <vector>

namespace anisocert::refiners::ls {

struct Theorem11Conditions {
  bool theta_admissible = false;
  double gamma_lo = 0, gamma_hi = 0;            // γ(θ_bound) ∈ [lo, hi] (when admissible)
  double separation_lo = 0, separation_hi = 0;  // 2 arcsin(γ²/2) in degrees
  std::vector<int> corners_failing, corners_undecided;
};

// metrics[k] is the metric at corner k.
Theorem11Conditions theorem11_conditions(const common::Domain& domain, const std::vector<predicates::Sym2<double>>& metrics,
                                         double theta_bound);

}  // namespace anisocert::refiners::ls
