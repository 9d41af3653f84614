#pragma once
// LS Theorem 11's conditions on a run, decided by theory/ and the exact angle predicate:
// θ_bound < arcsin(1/(2√2)), and at every vertex of the PSLG (Ω's corners, then its points) every
// two adjoining segments separated by at least 2 arcsin(γ²/2) in the vertex's metric, γ = γ(θ_bound) the root > 1 of
// γ⁸ + 2γ⁴√(γ²+1) sin θ_bound − γ⁴ − 1. (bdr_min(γ) > 0, the field's condition, is not decided
// here.) Like the star refiner's LU Lemma 4.1 line, this says where the termination guarantee
// holds, not what the run did.
#include "refiners/common/domain.hpp"
#include "refiners/common/subsegments.hpp"

#include <string>
#include <vector>

namespace anisocert::refiners::ls {

struct Theorem11Conditions {
  bool theta_admissible = false;
  double gamma_lo = 0, gamma_hi = 0;            // γ(θ_bound) ∈ [lo, hi] (when admissible)
  double separation_lo = 0, separation_hi = 0;  // 2 arcsin(γ²/2) in degrees
  std::vector<int> corners_failing, corners_undecided;  // X's vertices (domain.hpp: corners, then points)
};

// metrics[k] is the metric at X's vertex k.
Theorem11Conditions theorem11_conditions(const common::Domain& domain, const std::vector<predicates::Sym2<double>>& metrics,
                                         double theta_bound);

// For a stop near a vertex: "; refinement is running into corner k (x, y), where LS Theorem 11's
// separation fails" (or holds, or is undecided; or θ_bound is beyond the theorem), for a
// subsegment ab that ends at X's vertex k (sites 0 … V−1 are X's vertices); empty otherwise.
std::string corner_note(const common::Domain& domain, const Theorem11Conditions& c, int a, int b);

// corner_note above, bound to a run, for refiners/common/subsegments.hpp.
inline common::CornerNote corner_note(const common::Domain& domain, const Theorem11Conditions& c) {
  return [&domain, &c](int a, int b) { return corner_note(domain, c, a, b); };
}

// sin²θ_bound, or the double just above it: "angle ≥ arcsin √s2" then implies "angle ≥ θ_bound"
// exactly. At 30° and 45° it is the rational itself (1/4, 1/2), so that an angle of exactly
// θ_bound is no violator (LS §9: "an angle less than θ_bound").
double sin2_above(double theta_deg);

}  // namespace anisocert::refiners::ls
