#pragma once
// Whether cells (triangles, or convex polygons) with sites as vertices form a triangulation
// (polygonalization) of a domain, decided exactly (BWY §3.2.1; LS Theorem 7's conclusion; the
// certifier's "valid"). A certifying check, simpler than what produced the cells: with every cell
// strictly convex and counter-clockwise, and the cells' directed edges cancelling in pairs except
// for the boundary edges, the boundary of the 2-chain of cells is the cycle of boundary edges, so
// every point off the edges is covered as many times as that cycle winds around it. The check
// then makes the winding number 1 on the domain and 0 off it:
//  - a domain polygon Ω (the project's files): the boundary edges tile ∂Ω counter-clockwise;
//  - no polygon (a mesh from another mesher): the boundary edges form disjoint simple loops
//    (no site starts or ends two of them, no two meet except consecutively), and the loops
//    around each loop wind 0 times (counter-clockwise loop) or once (clockwise loop, a hole);
//    when the file declares edges, every boundary edge must be one of them (the triangles cover
//    the declared domain and no more), and every declared edge must be an edge of the cells.
// Besides: no two sites coincide, every site is a vertex of some cell.
// Cost: linear in the cells (edge pairing by counting sort, orientations on interval
// enclosures first), plus a grid for the boundary's crossings; failures are counted in full and
// the first `described` (by default max_failure_texts) are described.
#include "geometry/mesh.hpp"
#include "oracle/certify/enclosed_mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace anisocert::oracle {

inline constexpr std::size_t max_failure_texts = 1000;

struct TriangulationCheck {
  bool is_triangulation = false;
  std::vector<std::string> checks_run;
  std::vector<std::string> failures;          // the first `described`, each naming the cell, edge or site
  std::size_t failure_count = 0;              // all of them
  std::size_t described = max_failure_texts;
  std::vector<int> bad_cells;                 // every cell named by a failure (sorted, once each)
  std::vector<std::pair<int, int>> bad_edges; // every edge named by a failure
  void fail(std::string text);
};

// Cells as one flat list: cell k has the sites sites[begin[k]] .. sites[begin[k + 1] − 1],
// counter-clockwise; name(k) names it in messages ("triangle 12").
struct CellList {
  std::vector<int> sites;
  std::vector<std::size_t> begin{0};
  std::function<std::string(std::size_t)> name;
  std::size_t size() const { return begin.size() - 1; }
  void add(const int* first, std::size_t n) {
    sites.insert(sites.end(), first, first + n);
    begin.push_back(sites.size());
  }
};

CellList triangle_cells(const std::vector<std::array<int, 3>>& triangles);
// The edges of the cells, each once as (a, b) with a < b, sorted.
std::vector<std::pair<int, int>> unique_edges(const CellList& cells, std::size_t site_count);

// The domain: mesh.domain when it is not empty, else the union of the cells bounded by
// mesh.edges (when there are any). mesh.triangles is not read: the cells are given.
TriangulationCheck check_triangulation(const EnclosedMesh& mesh, const CellList& cells,
                                       std::size_t described = max_failure_texts);

}  // namespace anisocert::oracle
