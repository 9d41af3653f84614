#pragma once
// A 3D star kept as sites are added (issue 40: "only stars whose circumspheres a new site enters
// change"; LU Lemma 3.5: the conflict zone only shrinks). Bowyer–Watson restricted to the star of
// v: the tetrahedra (v, a, b, c) whose perturbed M-sphere (predicates/insphere_perturbed.hpp)
// holds the new site k are removed, and each face (v, a, b) between a removed and a kept
// tetrahedron is joined to k; with the perturbation the sites are in general position, so this is
// the star of v in the new perturbed Delaunay tetrahedralization, as gift wrapping would find it
// (tests/refiner_star3_test.cpp). Where the star is open (v on the hull of the sites) and k is on
// or beyond an open face's plane, or a removed tetrahedron borders the open part, the hull around v
// changes: the caller wraps the star again.
#include "refiners/star/gift_wrap3.hpp"

namespace anisocert::refiners::star {

enum class Star3Update { unchanged, updated, recompute };

Star3Update insert_into_star3(Star3& star, int v, int k, const std::vector<predicates::Point3<double>>& points,
                              const predicates::Sym3<double>& M);

}  // namespace anisocert::refiners::star
