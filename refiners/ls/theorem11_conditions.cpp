#include "refiners/ls/theorem11_conditions.hpp"

#include "predicates/angle.hpp"
#include "theory/ls_theorem11.hpp"

#include <algorithm>

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

std::string corner_note(const common::Domain& domain, const Theorem11Conditions& c, int a, int b) {
  const int m = static_cast<int>(domain.size());
  const int k = a < m ? a : b < m ? b : -1;
  if (k < 0) return "";
  const auto has = [k](const std::vector<int>& v) { return std::find(v.begin(), v.end(), k) != v.end(); };
  const std::string where = "; refinement is running into " + domain.corner_text(static_cast<std::size_t>(k));
  if (!c.theta_admissible) return where + " (θ_bound is above LS Theorem 11's limit)";
  if (has(c.corners_failing)) return where + ", where LS Theorem 11's separation of adjoining segments fails";
  if (has(c.corners_undecided)) return where + ", where LS Theorem 11's separation is undecided";
  return where + ", where LS Theorem 11's separation holds";
}

double sin2_above(double theta_deg) {
  if (theta_deg == 30) return 0.25;
  if (theta_deg == 45) return 0.5;
  return sqr(theory::ls_t11_sin_theta(rational_from_double(theta_deg), 128)).upper_double();
}

}  // namespace anisocert::refiners::ls
