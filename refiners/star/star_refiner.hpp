#pragma once
// Locally uniform anisotropic meshing with stars in 2D (Boissonnat, Wormser & Yvinec, LU §3–§4):
// every site v keeps its star S_v (star_set.hpp), refined by the rules of LU §4.1 in priority
// order (rules.hpp; rule 1 is the common edge level, refiners/common/boundary.hpp) until the stars
// are consistent, then merged. Refine(τ) picks a point with Pick_valid (pick_valid.hpp), and
// Insert_or_snap splits the boundary subsegment it would encroach instead.
// Floating point for constructions; every decision that shapes a star (orientation, in-circle,
// distance comparisons) and every encroachment and containment test is an exact filtered
// predicate. The choices made in floating point (which rule fires a hair early, where a point is
// picked, which candidates a search box holds, with margins named in the code) decide where the
// refiner inserts, never whether stars agree. The refiners never include the oracle (DESIGN.md
// § Layers); the exact certifier judges the output.
#include "fields/metric_field.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/refinement_loop.hpp"
#include "refiners/star/parameters.hpp"

#include <vector>

namespace anisocert::refiners::star {

struct StarResult : common::RefineResult {
  std::size_t inconsistent_triangles = 0;
  // Sites whose star has no triangle in Ω (a site of a mesh of Ω has one): never consistent.
  std::size_t empty_stars = 0;
  // LU Lemma 4.1 (rule 1 ends) needs every boundary angle > 90° in the metric; the corners of Ω
  // where the angle in the corner's metric is not.
  std::vector<int> acute_corners;
  // Pick_valid: points discarded as γ₀-cocircular, and refinements that kept a forbidden point.
  std::size_t picks_rejected = 0, picks_exhausted = 0;
  std::size_t refinements = 0;  // calls of Refine(τ) (rules 2–5), whatever they inserted or split
};

StarResult refine_star(const common::Domain& domain, const fields::MetricField& field, const RefineParameters& p,
                       const common::Progress& progress = {});
// The same on a polygon of doubles; throws common::DomainError when Domain refuses it.
StarResult refine_star(const common::Polygon<double>& domain, const fields::MetricField& field, const RefineParameters& p,
                       const common::Progress& progress = {});

}  // namespace anisocert::refiners::star
