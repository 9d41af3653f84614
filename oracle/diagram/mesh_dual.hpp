#pragma once
// Whether a mesh is the dual of the anisotropic Voronoi diagram of its own vertices (LS §5, the
// question of LS Theorem 7 asked of any mesh): each triangle of the mesh is decided exactly
// against D|Ω of its vertices with their metrics —
//   dual       its three vertices own one Voronoi vertex of D|Ω together, and nothing else;
//   tie        its vertices are three of the four or more owners of one Voronoi vertex (a
//              degenerate vertex, whose dual polygon any triangulation may split);
//   not dual   neither, with the part of D|Ω that shows it: two of its vertices whose cells share
//              no Voronoi arc, or the Voronoi vertices at which the arc of two of them ends,
//              whose owners do not include the third;
// and the dual triangles of D|Ω that are no triangle of the mesh are listed as missing.
#include "oracle/diagram/diagram.hpp"

#include <array>
#include <string>
#include <vector>

namespace anisocert::oracle {

struct MeshDual {
  enum class Kind { dual, tie, not_dual };
  std::vector<Kind> kinds;                            // per mesh triangle
  std::size_t dual = 0, ties = 0, not_dual = 0;       // counts of kinds
  struct NotDual {
    int triangle;
    std::string why;                                  // one line, naming sites, arcs and nodes by index
  };
  std::vector<NotDual> not_dual_witnesses;            // the first `described`
  std::vector<DualCell> missing;                      // dual triangles of D|Ω not in the mesh: the first `described`
  std::size_t missing_count = 0;
  std::size_t described = 0;
  // Every triangle dual or tie, and no dual triangle missing: the mesh is the dual of D|Ω.
  bool is_dual() const { return not_dual == 0 && missing_count == 0; }
};

// `triangles` index d.input.sites. `described`: how many witnesses of each list to write out.
MeshDual compare_with_dual(const Diagram& d, const std::vector<std::array<int, 3>>& triangles, std::size_t described);

}  // namespace anisocert::oracle
