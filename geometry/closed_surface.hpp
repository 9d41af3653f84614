#pragma once
// Whether oriented triangles bound a solid as a surface (issues 39 and 40: a tetrahedral mesh's
// boundary, a polyhedral domain): a closed, consistently oriented 2-manifold — every edge in
// exactly two triangles, once in each direction, and the triangles at a vertex one cycle around
// it (no pinched edge or vertex). Combinatorial: no coordinates.
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace anisocert::geometry {

struct SurfaceDefect {
  enum class Kind {
    edge_count,      // the edge (a, b) is in `count` ≠ 2 triangles (1: the surface is open there; ≥ 3: pinched)
    same_direction,  // the edge (a, b) runs the same way in its two triangles (inconsistent orientation)
    pinched_vertex,  // the triangles at vertex a make `count` > 1 cycles around it
  };
  Kind kind;
  int a = -1, b = -1;  // the edge, a < b; or the vertex a
  std::size_t count = 0;
};

// Calls found(defect) for every defect: the edges in increasing order of (a, b), then the vertices
// in increasing order. A vertex whose triangles do not close around it (an edge in one of them)
// is not reported again as pinched.
void closed_surface_defects(const std::vector<std::array<int, 3>>& triangles, const std::function<void(const SurfaceDefect&)>& found);

}  // namespace anisocert::geometry
