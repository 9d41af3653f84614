#pragma once
// Gmsh list-based post-processing views (https://gmsh.info/doc/texinfo/gmsh.html § Post-processing
// commands: `View "name" { TT(x1,y1,z1,x2,y2,z2,x3,y3,z3){t1,...,t27}; ... };`): the metric of a
// mesh as a tensor view, one TT (tensor triangle) per triangle with the 3×3 tensor of each of its
// vertices, row-major. This is what Gmsh's anisotropic 2D algorithm (BAMG, Mesh.Algorithm = 7)
// takes as a background field (Field PostView, or `gmsh -bgm FILE.pos`); Gmsh does not use a view
// defined on the mesh being generated, hence a file of its own. Written only: anisocert reads the
// same metric from the Gmsh .msh of the same mesh (its $NodeData).
#include "io/formats/mesh_file.hpp"

namespace anisocert::io {

// The planar metric M_v becomes diag-blocked [M_v 0; 0 m33] with m33 = m11 + m22 > 0, so the 3×3
// tensor is positive definite too; a planar mesher restricts it to the plane (Jᵀ M J), where it
// is M_v again. Throws InputError when the mesh has no metric or a number has no finite decimal.
std::vector<FileText> write_gmsh_view(const MeshFile& m, const std::string& path);

}  // namespace anisocert::io
