#pragma once
// The star of a site v in 3D (LU Definition 3.1, issue 40): the tetrahedra at v of Del_M of v and
// the candidates, perturbed symbolically where five are M-cospherical (predicates/
// insphere_perturbed.hpp), by gift wrapping around v. Every decision is an exact predicate.
//  - The first tetrahedron: a = the candidate M-nearest to v (the M-ball on va as diameter holds
//    no other candidate, so va is an edge of every Delaunay tetrahedralization, perturbed or not);
//    for b in order of M-distance from v, the tetrahedron beyond the triangle vab on each side
//    (as below), until one is empty of every candidate (checked against all: the order only
//    makes the search short). Some triangle vab is Delaunay, and beyond it on a side holding
//    candidates lies a Delaunay tetrahedron, so one is found unless v and the candidates are
//    coplanar.
//  - Then across each face (v, a, b) of a tetrahedron (v, a, b, c): the next tetrahedron is
//    (v, b, a, d) with d the candidate on the other side of the plane vab whose M-sphere through
//    v, a, b holds no other candidate of that side (one scan: on that side the spheres through
//    v, a, b are nested, and the perturbation orders them totally); none there: the face is on the
//    hull of the candidates (v's star is open there).
// Cost: O(k) predicates per face, and per triangle vab tried for the first tetrahedron (usually
// the first few), k candidates.
#include "predicates/point.hpp"

#include <array>
#include <vector>

namespace anisocert::refiners::star {

struct Star3 {
  std::vector<std::array<int, 3>> link;  // (a, b, c): the tetrahedron (v, a, b, c), positively oriented
  std::vector<std::array<int, 2>> open;  // (a, b): the face (v, a, b) of a star tetrahedron on its positive side, none beyond it
};

// The star of site v among `candidates` (indices into `points`, v not among them) in the metric M;
// empty when v and the candidates are coplanar. Sites are distinct.
Star3 gift_wrap_star3(int v, const std::vector<int>& candidates, const std::vector<predicates::Point3<double>>& points,
                      const predicates::Sym3<double>& M);

}  // namespace anisocert::refiners::star
