#pragma once
// Refine(τ) of LU §4.1: a random point of the picking region B_{M_v}(c, δr) of a triangle τ of S_v
// (c, r: τ's circumcentre and radius in M_v), drawn again while it would form a forbidden
// γ₀-cocircular configuration (Pick_valid, LU Definition 3.6 and 3.9), at most 1 + pick_attempts
// draws. A floating-point choice among points that are all valid refinements.
#include "geometry/circumellipse.hpp"
#include "refiners/common/sites.hpp"
#include "refiners/star/parameters.hpp"

#include <random>
#include <vector>

namespace anisocert::refiners::star {

struct PickCounts {
  std::size_t rejected = 0;   // picked points discarded as γ₀-cocircular
  std::size_t exhausted = 0;  // refinements that kept a forbidden point after pick_attempts discards
};

class PickValid {
 public:
  PickValid(const common::Domain& domain, const common::Sites& sites, const RefineParameters& p)
      : domain_(domain), sites_(sites), p_(p), rng_(p.seed) {}

  // A point of the picking region of the circumellipse c (in M) of the triangle (v, a, b); when
  // the region is below the resolution of doubles (non-finite), the triangle's centroid.
  predicates::Point2<double> pick(const geometry::Circumellipse<double>& c, const predicates::Sym2<double>& M, int v, int a,
                                  int b);
  const PickCounts& counts() const { return counts_; }

 private:
  // Whether x would form a forbidden configuration with the sites `cand` (those within about
  // 2 r_τ of the picking region, where x's new fan lies). Never for x outside Ω: it is not
  // inserted (Insert_or_snap splits a subsegment instead), and the field need not be defined
  // there (a background mesh that covers exactly Ω).
  bool forbidden(const predicates::Point2<double>& x, double r_tau, const std::vector<int>& cand) const;

  const common::Domain& domain_;
  const common::Sites& sites_;
  const RefineParameters& p_;
  std::mt19937 rng_;
  PickCounts counts_;
  std::vector<int> cand_;
};

}  // namespace anisocert::refiners::star
