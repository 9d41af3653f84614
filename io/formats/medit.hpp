#pragma once
// Medit .mesh/.meshb and .sol/.solb, as MMG and libMeshb write them (the libMeshb format
// specification, "The Meshb format"): MeshVersionFormatted 1–4 (1: 32-bit reals; 2: 64-bit
// reals; 3: also 64-bit positions in binary; 4: also 64-bit integers), Dimension 2, or 3: a
// tetrahedral mesh when it has Tetrahedra (MeshFile::dimension 3, the Triangles then its declared
// boundary), else a planar mesh with every z = 0, accepted only when allow_planar_3d; Vertices with
// references, Edges, Triangles, Tetrahedra, Corners, RequiredVertices, RequiredEdges, Ridges;
// Quadrilaterals, Prisms and Hexahedra are refused; other keywords are skipped (in binary, by the
// position of the next keyword the file declares). ASCII is read by token (a keyword and its
// value may be on separate lines). .sol: SolAtVertices with one solution of type 1 (a size h: the
// metric I/h²) or 3 (a symmetric tensor, the lower triangle by rows: m11 m12 m22 in 2D, m11 m12 m22
// m13 m23 m33 in 3D). Binary files in either byte order.
#include "io/formats/mesh_file.hpp"

#include <string_view>

namespace anisocert::io {

struct MeditOptions {
  bool allow_planar_3d = false;   // Dimension 3 with every z exactly 0
  bool allow_surface = false;     // Dimension 3, Triangles and no Tetrahedra: a surface, in mesh3
};

MeshFile read_medit(std::string_view bytes, const std::string& source, const MeditOptions& o = {});
MeshFile read_medit_file(const std::string& path, const MeditOptions& o = {});
std::vector<predicates::Sym2<Rational>> read_medit_sol(std::string_view bytes, const std::string& source);
std::vector<predicates::Sym2<Rational>> read_medit_sol_file(const std::string& path);
// A .sol of Dimension 3, for a tetrahedral mesh.
std::vector<predicates::Sym3<Rational>> read_medit_sol3(std::string_view bytes, const std::string& source);
std::vector<predicates::Sym3<Rational>> read_medit_sol3_file(const std::string& path);

enum class MeditEncoding { ascii, binary };
// version 1 (float reals: every number must be a float) to 4.
std::string medit_mesh_text(const MeshFile& m, MeditEncoding e = MeditEncoding::ascii, int version = 2);
std::string medit_sol_text(const std::vector<predicates::Sym2<Rational>>& metrics, MeditEncoding e = MeditEncoding::ascii,
                           int version = 2);
std::string medit_sol_text(const std::vector<predicates::Sym3<Rational>>& metrics, MeditEncoding e = MeditEncoding::ascii,
                           int version = 2);
// path.mesh or path.meshb (by its extension), with path's .sol/.solb beside it when m has metrics.
std::vector<FileText> write_medit_file(const MeshFile& m, const std::string& path);
FileText write_medit_sol(const std::vector<predicates::Sym2<Rational>>& metrics, const std::string& path);
FileText write_medit_sol3(const std::vector<predicates::Sym3<Rational>>& metrics, const std::string& path);

}  // namespace anisocert::io
