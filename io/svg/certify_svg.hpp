#pragma once
// The certifier's picture: the mesh with every triangle and edge a failing check names coloured
// (validity, local uniformity, quality and angle bounds in red; edges outside the length range or
// named by validity in orange), and under it two histograms — the metric edge lengths (log
// scale, the unit band [1/√2, √2] shaded) and the mean-ratio qualities — because a picture of
// 100k triangles is read faster than a list.
#include "geometry/mesh.hpp"
#include "geometry/mesh3.hpp"
#include "io/reports/certify_report.hpp"

#include <string>

namespace anisocert::io {

std::string certify_svg(const geometry::Mesh<Rational>& mesh, const oracle::CertifyReport& r, const std::string& caption);
// A tetrahedral mesh (issue 39): its section by the plane z = (z_min + z_max)/2, each tetrahedron
// cut there drawn as its convex section (failing ones in red), and the histograms of edge
// lengths, qualities and each tetrahedron's smallest dihedral angle.
std::string certify_svg(const geometry::Mesh3<Rational>& mesh, const oracle::Certify3Report& r, const std::string& caption);

}  // namespace anisocert::io
