#pragma once
// The tetrahedral mesh (issue 39), the 3D twin of Mesh<S> (DESIGN.md: Point3, Metric3 and the
// tetrahedral mesh beside their 2D twins): vertices with their metrics (LU §2: M_v symmetric
// positive definite), tetrahedra and the boundary triangles a file declares, by vertex index.
// S = Rational (read from a file, the certifier) or double (each double the rational it is).
#include "predicates/point.hpp"

#include <array>
#include <vector>

namespace anisocert::geometry {

using predicates::Point3;
using predicates::Sym3;

template <class S>
struct Mesh3 {
  std::vector<Point3<S>> vertices;
  std::vector<Sym3<S>> metrics;                 // empty, or metrics[i] belongs to vertices[i]
  std::vector<std::array<int, 4>> tetrahedra;   // positively oriented when valid (or all negatively)
  // The boundary triangles a file declares (Medit Triangles, Gmsh triangles): when there are any,
  // they must be exactly the boundary faces of the tetrahedra, in either orientation.
  std::vector<std::array<int, 3>> triangles;
};

}  // namespace anisocert::geometry
