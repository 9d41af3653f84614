#include "refiners/ls/theorem11_conditions.hpp"

#include "predicates/angle.hpp"
#include "theory/ls_theorem11.hpp"

namespace anisocert::refiners::ls {

Theorem11Conditions theorem11_conditions(const common::Domain& domain, const std::vector<predicates::Sym2<double>>& metrics,
                                         double theta_bound) {
  Theorem11Conditions c;
  const Rational theta = rational_from_double(theta_bound);
  c.theta_admissible = theory::ls_t11_theta_admissible(theta);
  if (!c.theta_admissible) return c;
  const Interval gamma = theory::ls_t11_gamma(theta, 128);
  const Interval separation = theory::ls_t11_segment_angle_deg(gamma);
  c.gamma_lo = gamma.lower_double(), c.gamma_hi = gamma.upper_double();
  c.separation_lo = separation.lower_double(), c.separation_hi = separation.upper_double();
  // The angle ≥ 2 arcsin(γ²/2) ⇔ its cosine ≤ cos(2 arcsin(γ²/2)) = 1 − γ⁴/2.
  const Interval cos_separation = 1 - sqr(sqr(gamma)) / 2;
  const double k_lo = cos_separation.lower_double(), k_hi = cos_separation.upper_double();
  const auto& p = domain.corners();
  const std::size_t n = p.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto& before = p[(k + n - 1) % n];
    const auto& after = p[(k + 1) % n];
    if (predicates::compare_angle_cos(before, p[k], after, metrics[k], k_lo) != Sign::positive) continue;  // holds
    if (predicates::compare_angle_cos(before, p[k], after, metrics[k], k_hi) == Sign::positive)
      c.corners_failing.push_back(static_cast<int>(k));
    else
      c.corners_undecided.push_back(static_cast<int>(k));
  }
  return c;
}

}  // namespace anisocert::refiners::ls
