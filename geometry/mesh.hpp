#pragma once
// The one mesh shape every layer passes (DESIGN.md § Layers): sites with their metrics (LS §2:
// M_v symmetric positive definite), the domain Ω, the constrained segments and the triangles, by
// site index. A site set for the diagram is a Mesh without triangles. S = Rational (read from a
// file, the oracle and the certifier) or double (the refiners' output, each double denoting the
// rational it is).
#include "geometry/polygon.hpp"

#include <array>
#include <utility>
#include <vector>

namespace anisocert::geometry {

using predicates::Sym2;

template <class S>
struct Mesh {
  std::vector<Point2<S>> sites;
  std::vector<Sym2<S>> metrics;                // metrics[i] belongs to sites[i]; positive definite
  Polygon<S> domain;                           // simple, counter-clockwise
  std::vector<std::pair<int, int>> segments;   // constrained segments
  // The edges a mesh file declares (Medit Edges, Gmsh lines, Triangle and FreeFem boundary
  // edges): each must be an edge of the triangles; with no domain polygon, the boundary of the
  // union of the triangles must consist of them (when there are any).
  std::vector<std::pair<int, int>> edges;
  std::vector<std::array<int, 3>> triangles;   // counter-clockwise when valid (the certifier's verdict)
};

// The same mesh with every double replaced by the rational it denotes (exact); a NaN or an
// infinity throws NumberSyntaxError naming it.
Mesh<Rational> exact(const Mesh<double>& m);

}  // namespace anisocert::geometry
