#pragma once
// The faces of a tetrahedral mesh grouped by their vertices (issue 39): the validity check pairs
// them (tetrahedralization_check.hpp), the sliver measure takes the pairs (quasi_cosphericity.hpp).
#include <array>
#include <cstddef>
#include <vector>

namespace anisocert::oracle {

// The face of tetrahedron `tetrahedron` opposite its vertex number `opposite` (0 to 3), its
// vertices in increasing order.
struct TetrahedronFace {
  std::array<int, 3> sorted;
  int tetrahedron;
  int opposite;
};

// Every tetrahedron's four faces ordered by (sorted, tetrahedron, opposite): equal faces are
// adjacent. The order of a comparison sort, in linear time: bucketed by the least vertex (a
// counting sort over the `vertices` indices), each bucket's few faces sorted.
std::vector<TetrahedronFace> faces_in_order(const std::vector<std::array<int, 4>>& tetrahedra, std::size_t vertices);

}  // namespace anisocert::oracle
