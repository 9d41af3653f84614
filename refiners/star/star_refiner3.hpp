#pragma once
// Locally uniform anisotropic meshing with stars in 3D (LU §3–§4, "we present the results in
// dimension 3"; issue 40), star_refiner.hpp's twin: every site v keeps its star S_v
// (star_set3.hpp), refined by the rules of LU §4.1 in priority order (rules3.hpp; rule 1 is the
// surface level, refiners/common/boundary3.hpp) until the stars are consistent, then merged.
// Refine(τ) picks a point with Pick_valid (pick_valid3.hpp), and Insert_or_snap splits the
// subsegment or subfacet it would encroach instead. As in 2D, floating point chooses where to
// insert; every decision that shapes a star or the boundary is an exact predicate, and the exact
// 3D certifier (oracle/certify/mesh_certifier3.hpp, which the refiner never includes) judges the
// output.
#include "fields/metric_field.hpp"
#include "refiners/common/domain3.hpp"
#include "refiners/common/refinement_loop.hpp"
#include "refiners/star/parameters.hpp"

#include <vector>

namespace anisocert::refiners::star {

struct StarResult3 : common::RefineResult3 {
  std::size_t inconsistent_tetrahedra = 0;
  std::size_t empty_stars = 0;  // sites whose star has no tetrahedron in Ω
  std::size_t picks_rejected = 0, picks_exhausted = 0;
  std::size_t refinements = 0;  // calls of Refine(τ) (rules 2–5)
  std::size_t boundary_splits = 0;  // rule 1 and Insert_or_snap's splits
  std::size_t snap_splits = 0;      // of those, Insert_or_snap's (a picked point encroached)
  std::size_t subfacets = 0;        // of the surface level when the run ended
  // The mesh's boundary triangles (mesh.triangles: the faces of one tetrahedron) whose three
  // vertices lie in no one plane of Ω's facets: where the mesh does not conform to Ω (0 for a
  // consistent output).
  std::size_t faces_off_boundary = 0;
  // LU Lemma 4.1 (rule 1 ends) needs every dihedral angle of Ω above 90° in the metric: Ω's
  // ridges, and those where the angle in an end's metric is not (common::Boundary3::ridge_angles).
  std::size_t ridges = 0;
  std::vector<std::array<int, 2>> right_or_acute_ridges;
};

// Throws common::FieldError when the field is not a metric where a site is inserted.
StarResult3 refine_star3(const common::Domain3& domain, const fields::MetricField3& field, const RefineParameters& p,
                         const common::Progress& progress = {});

}  // namespace anisocert::refiners::star
