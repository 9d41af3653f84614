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
  // At each vertex of X, every two segments that meet there (at a corner without interior
  // segments, its two edges).
  const auto& p = domain.vertices();
  std::vector<std::vector<int>> far(p.size());
  for (std::size_t e = 0; e < domain.segment_count(); ++e) {
    const auto [a, b] = domain.segment_ends(e);
    far[static_cast<std::size_t>(a)].push_back(b), far[static_cast<std::size_t>(b)].push_back(a);
  }
  for (std::size_t k = 0; k < p.size(); ++k) {
    bool failing = false, undecided = false;
    for (std::size_t i = 0; i < far[k].size(); ++i)
      for (std::size_t j = i + 1; j < far[k].size(); ++j) {
        const auto &u = p[static_cast<std::size_t>(far[k][i])], &w = p[static_cast<std::size_t>(far[k][j])];
        if (predicates::compare_angle_cos(u, p[k], w, metrics[k], k_lo) != Sign::positive) continue;  // holds
        if (predicates::compare_angle_cos(u, p[k], w, metrics[k], k_hi) == Sign::positive)
          failing = true;
        else
          undecided = true;
      }
    if (failing) c.corners_failing.push_back(static_cast<int>(k));
    else if (undecided) c.corners_undecided.push_back(static_cast<int>(k));
  }
  return c;
}

std::string corner_note(const common::Domain& domain, const Theorem11Conditions& c, int a, int b) {
  const int m = static_cast<int>(domain.vertices().size());
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
