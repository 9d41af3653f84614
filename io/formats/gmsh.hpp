#pragma once
// Gmsh .msh (https://gmsh.info/doc/texinfo/gmsh.html § MSH file format): version 4.1, ASCII and
// binary, and version 2.2, ASCII. Read: $Nodes (entity blocks in 4.1), $Elements — triangles
// (type 2), 4-node tetrahedra (type 4) and boundary lines (type 1, with their physical tag as the
// edge reference); quadrangles, hexahedra, prisms, pyramids and higher-order elements are refused,
// points skipped; a planar mesh (every z = 0) or a tetrahedral one — and a metric from $NodeData
// with 9 components (a 3×3 tensor, row-major: symmetry checked exactly, and for the planar mesh
// the z-row and z-column ignored), 3 (m11 m12 m22, planar only) or 1 (a size h: I/h²). Node tags may be sparse;
// sites are numbered in the order of the $Nodes section. Written: 4.1 ASCII (or binary), the
// metric as a 9-component $NodeData when the mesh has metrics.
#include "io/formats/mesh_file.hpp"

#include <string_view>

namespace anisocert::io {

bool looks_like_gmsh(std::string_view head);          // starts with "$MeshFormat"
// surface: a file with triangles and no tetrahedra is a surface in space, read into mesh3.
MeshFile read_gmsh(std::string_view bytes, const std::string& source, bool surface = false);
MeshFile read_gmsh_file(const std::string& path, bool surface = false);

enum class GmshEncoding { ascii, binary };
std::string gmsh_text(const MeshFile& m, GmshEncoding encoding = GmshEncoding::ascii);
std::vector<FileText> write_gmsh_file(const MeshFile& m, const std::string& path);  // .msh, ASCII 4.1

}  // namespace anisocert::io
