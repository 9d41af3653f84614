#pragma once
// A picture of D|Ω (SVG): the domain, each face tinted by its site, orphans hatched and outlined,
// each site with its metric's unit ellipse (scaled), arcs (wedged blue, unwedged red), Voronoi
// vertices, the dual triangles, and the witness points of wedge violations; a caption line
// under the legend when one is given.
#include "oracle/diagram/diagram.hpp"

#include <string>

namespace anisocert::io {

std::string diagram_svg(const oracle::Diagram& d, const std::string& caption = "");

}  // namespace anisocert::io
