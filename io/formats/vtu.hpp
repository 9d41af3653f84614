#pragma once
// VTK XML unstructured grid (.vtu), as VTK, ParaView, Omega_h and Pragmatic write it (VTK's "VTK
// File Formats", XML section, and Kitware's wiki page "VTK XML Formats"): one Piece of
// NumberOfPoints points and NumberOfCells cells (connectivity, offsets, types). A DataArray is in
// format "ascii" (numbers as text), "binary" (base64 of a byte-count header and the data; with
// compressor="vtkZLibDataCompressor", of the block header [blocks, block size, last block size,
// compressed sizes…] and the zlib blocks) or "appended" (at its offset into <AppendedData
// encoding="raw" | "base64">, after the "_"), with header_type UInt32 (the default) or UInt64, in
// either byte_order. Header and data encoded as one base64 stream or as two are both read.
// Cells of type 10 (tetrahedron) make a tetrahedral mesh, whose type-5 triangles are its declared
// boundary; with type-5 triangles only the mesh is a triangle mesh, and every z must be exactly 0.
// Other cell types are refused by name. The metric is the point-data array named "metric" (any
// case; other arrays are skipped): 1 component (a size h: I/h²), 6 (xx yy zz xy yz xz: VTK's
// SymmetricTensor and Omega_h's order) or 9 (row by row, symmetric exactly); for a triangle mesh 1,
// 3 (xx yy xy) or 4 (row by row). Reals are the rationals they are: text as the rational it denotes
// (parse_input_number), Float32 and Float64 exactly. Failures are one line naming the file, the
// line (or, in appended raw data, the byte) and the array.
#include "io/formats/mesh_file.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace anisocert::io {

MeshFile read_vtu(std::string_view bytes, const std::string& source);
MeshFile read_vtu_file(const std::string& path);
// ASCII, every number an exact decimal (refused when it has none); the metric as "metric" with 6
// components in 3D (xx yy zz xy yz xz) and 3 in 2D (xx yy xy); a tetrahedral mesh's declared
// triangles as type-5 cells after its tetrahedra.
std::string vtu_text(const MeshFile& m);
std::vector<FileText> write_vtu_file(const MeshFile& m, const std::string& path);

}  // namespace anisocert::io
