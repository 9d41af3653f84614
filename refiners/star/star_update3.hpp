#pragma once
// A 3D star kept as sites are added (issue 40: "only stars whose circumspheres a new site enters
// change"; LU Lemma 3.5: the conflict zone only shrinks). Bowyer–Watson restricted to the star of
// v, with v's open faces (v on the hull of the sites) as ghost tetrahedra through a vertex at
// infinity: the tetrahedra (v, a, b, c) whose perturbed M-sphere (predicates/
// insphere_perturbed.hpp) holds the new site k are removed, and so are the ghosts k lies strictly
// beyond, or in the plane of inside the face's circle (the tetrahedron behind the face then in
// conflict too); each face at v between the removed and the kept is joined to k, and the open
// faces are the new link's edges without a reverse. With the perturbation the sites are in
// general position but for coplanarity, which the ghosts' rule settles as the perturbed spheres
// do, so this is the star of v in the new perturbed Delaunay tetrahedralization, as gift wrapping
// would find it (tests/refiner_star3_test.cpp). A configuration Bowyer–Watson does not assume
// (a new tetrahedron not positively oriented, a directed edge twice) asks the caller to wrap the
// star again.
#include "refiners/star/gift_wrap3.hpp"

namespace anisocert::refiners::star {

enum class Star3Update { unchanged, updated, recompute };

Star3Update insert_into_star3(Star3& star, int v, int k, const std::vector<predicates::Point3<double>>& points,
                              const predicates::Sym3<double>& M);

}  // namespace anisocert::refiners::star
