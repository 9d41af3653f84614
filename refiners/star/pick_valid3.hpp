#pragma once
// Refine(τ) of LU §4.1 in dimension 3 (issue 40), pick_valid.hpp's twin: a random point of the
// picking region B_{M_v}(c, δr) of a tetrahedron τ of S_v (c, r: its M_v-circumcentre and radius),
// drawn again while it would form a forbidden γ₀-cospherical configuration (Pick_valid, LU
// Definitions 3.6 and 3.9; predicates/quasi_cospherical.hpp decides each exactly), at most
// 1 + pick_attempts draws. A floating-point choice among points that are all valid refinements.
#include "refiners/common/sites3.hpp"
#include "refiners/star/parameters.hpp"
#include "refiners/star/pick_valid.hpp"

#include <random>
#include <vector>

namespace anisocert::refiners::star {

class PickValid3 {
 public:
  PickValid3(const common::Domain3& domain, const common::Sites3& sites, const RefineParameters& p)
      : domain_(domain), sites_(sites), p_(p), rng_(p.seed) {}

  // A point of the picking region of the M-sphere (centre o, squared radius r2) of the tetrahedron
  // q; its centroid when the region is below the resolution of doubles (non-finite).
  predicates::Point3<double> pick(const predicates::Point3<double>& o, double r2, const predicates::Sym3<double>& M,
                                  const std::array<int, 4>& q);
  const PickCounts& counts() const { return counts_; }

 private:
  // Whether x would make a new tetrahedron xpqr with γ(xpqr) < γ₀ (its metrics pairwise within γ₀)
  // that is γ₀-cospherical in M_x with a site s, with M_x-radius < β r_τ and radius-edge ratio
  // < ρ₀ over the five (LU's Pick_valid). The new tetrahedra are x's prospective star in M_x among
  // the sites `cand_` (those within (2 + δ) r_τ of the centre), and s ranges over the candidates in
  // the shell between r/γ₀² and rγ₀² from the new sphere's centre in M_x (a floating-point choice
  // of which configurations to test; each test is exact).
  bool forbidden(const predicates::Point3<double>& x, double r_tau);

  const common::Domain3& domain_;
  const common::Sites3& sites_;
  const RefineParameters& p_;
  std::mt19937 rng_;
  PickCounts counts_;
  std::vector<int> cand_, local_index_;
  std::vector<predicates::Point3<double>> local_;
};

}  // namespace anisocert::refiners::star
