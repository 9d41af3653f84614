#pragma once
// FreeFem++'s own mesh file .msh (FreeFem++ manual § Mesh generation, "Data structures and
// read/write statements for a mesh": "nv nt nbe", then nv lines "x y label", nt lines
// "i j k label", nbe lines "i j label", 1-based) and BAMG's metric file .mtr ("nbv 1" then nbv
// sizes h, the metric I/h²; or "nbv 3" then nbv lines a11 a21 a22).
#include "io/formats/mesh_file.hpp"

#include <string_view>

namespace anisocert::io {

bool looks_like_freefem(std::string_view head);     // starts with three integers
MeshFile read_freefem(std::string_view text, const std::string& source);
MeshFile read_freefem_file(const std::string& path);
std::vector<FileText> write_freefem_file(const MeshFile& m, const std::string& path);  // .msh (+ .mtr with metrics)

std::vector<predicates::Sym2<Rational>> read_bamg_metric(std::string_view text, const std::string& source);
std::vector<predicates::Sym2<Rational>> read_bamg_metric_file(const std::string& path);
FileText write_bamg_metric(const std::vector<predicates::Sym2<Rational>>& metrics, const std::string& path);

}  // namespace anisocert::io
