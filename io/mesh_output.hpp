#pragma once
// Writing a refiner's mesh (floating-point vertices and per-vertex metrics): the certifier's JSON
// (DESIGN.md site-set format plus "triangles", every double written as its exact decimal
// expansion so that `anisocert certify` reads exactly the numbers the refiner produced), Medit
// .mesh + .sol (the per-vertex metric as a symmetric tensor m11 m12 m22, the format MMG reads),
// and an SVG picture.
#include "geometry/mesh.hpp"

#include <string>

namespace anisocert::io {

using MeshData = geometry::Mesh<double>;

std::string mesh_json(const MeshData& m);
std::string medit_mesh(const MeshData& m);
std::string medit_sol(const MeshData& m);
std::string mesh_svg(const MeshData& m, const std::string& caption);

}  // namespace anisocert::io
