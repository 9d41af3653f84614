#pragma once
// The domain a triangle mesh covers, as the oracle takes a domain (LS §5: Ω a simple polygon):
// the boundary of the union of its triangles, when that boundary is one simple closed loop.
// Each triangle is taken counter-clockwise (by its exact orientation); the directed edges whose
// reverse is no triangle's edge form the boundary; corners where the boundary runs straight on
// are dropped (Ω is the same set). What `anisocert dual` gives the oracle for a mesh file.
#include "geometry/mesh.hpp"

#include <stdexcept>

namespace anisocert::geometry {

// Throws std::invalid_argument with one line on why there is no such polygon: a degenerate
// triangle, a boundary that is not one loop (a hole, several pieces, a vertex where the boundary
// passes twice), or a loop that is not simple.
Polygon<Rational> boundary_polygon(const Mesh<Rational>& m);

}  // namespace anisocert::geometry
