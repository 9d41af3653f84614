#pragma once
// The report of `anisocert dual` (oracle/diagram/mesh_dual.hpp): the full text and the --json
// object (docs/cli.md § dual documents every field), both bounded by the comparison's `described`
// witnesses per list; and the picture, the mesh's triangles coloured by kind.
#include "oracle/diagram/mesh_dual.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace anisocert::io {

std::string dual_text(const oracle::Diagram& d, const oracle::MeshDual& m, const std::string& input, const std::string& metric_source);
nlohmann::ordered_json dual_json(const oracle::Diagram& d, const oracle::MeshDual& m, const std::string& metric_source);
std::string dual_svg(const geometry::Mesh<Rational>& mesh, const oracle::Diagram& d, const oracle::MeshDual& m, const std::string& caption);

}  // namespace anisocert::io
