#pragma once
// Whether cells (triangles, or convex polygons) with sites as vertices form a triangulation
// (polygonalization) of a simple polygon Ω, decided exactly (BWY §3.2.1; LS Theorem 7's
// conclusion; the certifier's "valid"). A certifying check, simpler than what produced the cells:
// with every cell strictly convex and counter-clockwise, and the cells' directed edges cancelling
// in pairs except for edges that tile ∂Ω counter-clockwise, the boundary of the 2-chain of cells
// is ∂Ω, so every point of Ω off the edges is covered exactly once (its coverage is the winding
// number of ∂Ω about it) and no point outside is covered.
#include "numbers/rational.hpp"
#include "predicates/point.hpp"

#include <string>
#include <vector>

namespace anisocert::oracle {

struct TriangulationCheck {
  bool is_triangulation = false;
  std::vector<std::string> checks_run;
  std::vector<std::string> failures;          // each names the offending cell, edge or site
};

struct Cell {
  std::string name;                           // for messages: "triangle 12", "the dual cell of vertex 6"
  std::vector<int> sites;                     // counter-clockwise
};

TriangulationCheck check_triangulation(const std::vector<predicates::Point2<Rational>>& sites,
                                       const std::vector<predicates::Point2<Rational>>& domain,
                                       const std::vector<Cell>& cells);

}  // namespace anisocert::oracle
