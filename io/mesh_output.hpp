#pragma once
// Writing a refiner's mesh (floating-point vertices and per-vertex metrics): the certifier's JSON
// (DESIGN.md site-set format plus "triangles", every double written as its exact decimal
// expansion so that `anisocert certify` reads exactly the numbers the refiner produced), Medit
// .mesh + .sol (the per-vertex metric as a symmetric tensor m11 m12 m22, the format MMG reads),
// and an SVG picture.
#include "oracle/certify/mesh_certifier.hpp"
#include "predicates/point.hpp"

#include <array>
#include <string>
#include <vector>

namespace anisocert::io {

struct MeshData {
  std::vector<predicates::Point2<double>> sites;
  std::vector<predicates::Sym2<double>> metrics;
  std::vector<predicates::Point2<double>> domain;
  std::vector<std::pair<int, int>> segments;
  std::vector<std::array<int, 3>> triangles;
};

std::string mesh_json(const MeshData& m);
// The same mesh with every double taken as the rational it denotes (for the exact certifier).
oracle::Mesh<Rational> exact_mesh(const MeshData& m);
std::string medit_mesh(const MeshData& m);
std::string medit_sol(const MeshData& m);
std::string mesh_svg(const MeshData& m, const std::string& caption);

}  // namespace anisocert::io
