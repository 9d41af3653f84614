#pragma once
// A polyhedral domain Ω in 3D (issue 40; LU §4 meshes a polyhedron), as a surface of triangles:
// the 3D twin of polygon.hpp's simple counter-clockwise polygon. Every decision exact
// (predicates/orientation3.hpp on the rationals the file's numbers denote).
#include "numbers/rational.hpp"
#include "predicates/point.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace anisocert::geometry {

struct Polyhedron {
  std::vector<predicates::Point3<Rational>> vertices;
  std::vector<std::array<int, 3>> facets;  // outward: counter-clockwise seen from outside
};

// The first reason the facets do not bound a solid with outward orientation, one line naming
// facets and vertices numbered from 0, checked in this order:
//  - a facet names a vertex out of range, or one vertex twice; a facet's vertices are collinear;
//  - the surface is not a closed, consistently oriented 2-manifold (closed_surface.hpp: an edge in
//    one facet or in three or more, an edge run the same way twice, a pinched vertex);
//  - it is inward: the enclosed signed volume (Σ det[a − o, b − o, c − o] / 6) is not positive;
//  - two facets meet where they should not: facets sharing no vertex meet at all, facets sharing
//    one vertex meet elsewhere, facets sharing an edge overlap (coplanar, on the same side of it).
// Nothing when the facets are the outward surface of a solid. Pairs are found through their
// bounding boxes (a sweep in x), each decided by exact segment–triangle tests.
std::optional<std::string> polyhedron_defect(const Polyhedron& p);

// Whether facets t and u (indices into `vertices`, each three non-collinear points) meet where two
// facets of a surface must not: anywhere when they share no vertex; elsewhere than at the shared
// vertex; overlapping when they share an edge (coplanar, both on one side of it).
bool facets_meet(const std::vector<predicates::Point3<Rational>>& vertices, const std::array<int, 3>& t, const std::array<int, 3>& u);

}  // namespace anisocert::geometry
