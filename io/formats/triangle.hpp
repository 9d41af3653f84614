#pragma once
// Shewchuk's Triangle files (https://www.cs.cmu.edu/~quake/triangle.html: .node, .ele, .poly):
// BASE.node (vertices, optional attributes and boundary markers), BASE.ele (triangles of 3
// nodes, optional attributes), and BASE.poly when it exists (segments with boundary markers as
// the mesh's edges, and holes). Index base 0 or 1, as the first vertex number says. '#' starts a
// comment. Any of BASE.node, BASE.ele or BASE.poly may be given as the path.
// TetGen's files (TetGen 1.5 manual § 5.2) are their 3D sibling and read here too: a .node of
// dimension 3 makes BASE.ele a list of 4-node tetrahedra (region attribute as reference) and
// BASE.face, when it exists, the declared boundary faces (with their markers); BASE.face may be
// given as the path.
#include "io/formats/mesh_file.hpp"

namespace anisocert::io {

MeshFile read_triangle_files(const std::string& path);
// From the texts (poly and face may be empty: no such file); sources name them in messages.
MeshFile read_triangle(std::string_view node, std::string_view ele, std::string_view poly, const std::string& base,
                       std::string_view face = {});
std::vector<FileText> write_triangle_files(const MeshFile& m, const std::string& path);  // BASE.node/.ele/.poly (3D: .face)

}  // namespace anisocert::io
