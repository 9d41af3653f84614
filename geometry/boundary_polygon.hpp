#pragma once
// The domain a triangle mesh covers, as the oracle takes a domain (LS §5: Ω a simple polygon):
// the boundary of the union of its triangles, when that boundary is one simple closed loop.
// Each triangle is taken counter-clockwise (by its exact orientation); the directed edges whose
// reverse is no triangle's edge form the boundary; corners where the boundary runs straight on
// are dropped (Ω is the same set). What `anisocert dual` gives the oracle for a mesh file.
#include "geometry/mesh.hpp"

#include <stdexcept>

namespace anisocert::geometry {

// The boundary's vertices, by index into m.sites, counter-clockwise around the union of the
// triangles, every boundary vertex kept (also where the boundary runs straight on): what
// `anisocert refine --from` starts from. Throws std::invalid_argument with one line on why there
// is no such loop: a degenerate triangle, two triangles on the same side of an edge, a boundary
// that is not one loop (a hole, several pieces, a vertex where the boundary passes twice).
std::vector<int> boundary_loop(const Mesh<Rational>& m);

// The polygon without the corners where its boundary runs straight on (the same set).
Polygon<Rational> without_straight_corners(const Polygon<Rational>& p);

// The loop as a polygon without its straight corners; throws as boundary_loop does, and when the
// loop is not simple.
Polygon<Rational> boundary_polygon(const Mesh<Rational>& m);

}  // namespace anisocert::geometry
