#pragma once
// A picture of a mesh: its triangles over the domain, with a caption.
#include "geometry/mesh.hpp"

#include <string>

namespace anisocert::io {

std::string mesh_svg(const geometry::Mesh<double>& m, const std::string& caption);

}  // namespace anisocert::io
