#pragma once
// Medit .mesh + .sol (ASCII, MeshVersionFormatted 2: 64-bit reals), the format MMG reads: the
// vertices (z = 0 for the 2D mesh with reference 0), the boundary subsegments as Edges (reference
// 1), the triangles, and the per-vertex metric as a symmetric tensor m11 m12 m22 (SolAtVertices,
// type 3). Doubles are written with 17 significant digits, which read back as the same doubles.
#include "geometry/mesh.hpp"

#include <string>

namespace anisocert::io {

std::string medit_mesh(const geometry::Mesh<double>& m);
std::string medit_sol(const geometry::Mesh<double>& m);

}  // namespace anisocert::io
