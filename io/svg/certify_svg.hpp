#pragma once
// The certifier's picture: the mesh with every triangle and edge a failing check names coloured
// (validity, local uniformity, quality and angle bounds in red; edges outside the length range or
// named by validity in orange), and under it two histograms — the metric edge lengths (log
// scale, the unit band [1/√2, √2] shaded) and the mean-ratio qualities — because a picture of
// 100k triangles is read faster than a list.
#include "geometry/mesh.hpp"
#include "io/reports/certify_report.hpp"

#include <string>

namespace anisocert::io {

std::string certify_svg(const geometry::Mesh<Rational>& mesh, const oracle::CertifyReport& r, const std::string& caption);

}  // namespace anisocert::io
