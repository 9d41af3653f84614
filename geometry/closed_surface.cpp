#include "geometry/closed_surface.hpp"

#include <algorithm>
#include <tuple>

namespace anisocert::geometry {

void closed_surface_defects(const std::vector<std::array<int, 3>>& triangles, const std::function<void(const SurfaceDefect&)>& found) {
  using Kind = SurfaceDefect::Kind;
  // Each edge of each triangle by its ends, and whether it runs from the lesser to the greater.
  struct Directed {
    int lo, hi;
    bool forward;
  };
  std::vector<Directed> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& f : triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const int p = f[k], q = f[(k + 1) % 3];
      edges.push_back({std::min(p, q), std::max(p, q), p < q});
    }
  std::sort(edges.begin(), edges.end(),
            [](const Directed& x, const Directed& y) { return std::tie(x.lo, x.hi, x.forward) < std::tie(y.lo, y.hi, y.forward); });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    if (j - i != 2) found({Kind::edge_count, edges[i].lo, edges[i].hi, j - i});
    else if (edges[i].forward == edges[i + 1].forward) found({Kind::same_direction, edges[i].lo, edges[i].hi, 2});
    i = j;
  }
  // The link of v: for each triangle (v, q, r), rotated to start at v, the edge q → r.
  struct Link {
    int v, q, r;
  };
  std::vector<Link> links;
  links.reserve(3 * triangles.size());
  for (const auto& f : triangles)
    for (std::size_t k = 0; k < 3; ++k) links.push_back({f[k], f[(k + 1) % 3], f[(k + 2) % 3]});
  std::sort(links.begin(), links.end(), [](const Link& x, const Link& y) { return std::tie(x.v, x.q) < std::tie(y.v, y.q); });
  for (std::size_t i = 0; i < links.size();) {
    std::size_t j = i + 1;
    while (j < links.size() && links[j].v == links[i].v) ++j;
    // Cycles of q ↦ r among links[i, j) (sorted by q: a binary search per step).
    std::vector<char> seen(j - i, 0);
    std::size_t cycles = 0;
    bool broken = false;
    for (std::size_t s = i; s < j && !broken; ++s) {
      if (seen[s - i]) continue;
      ++cycles;
      std::size_t at = s;
      for (std::size_t steps = 0; steps <= j - i; ++steps) {
        seen[at - i] = 1;
        const int next = links[at].r;
        const auto hit = std::lower_bound(links.begin() + static_cast<long>(i), links.begin() + static_cast<long>(j), next,
                                          [](const Link& x, int q) { return x.q < q; });
        if (hit == links.begin() + static_cast<long>(j) || hit->q != next) {
          broken = true;  // an open fan: an edge in one triangle, reported above
          break;
        }
        at = static_cast<std::size_t>(hit - links.begin());
        if (at == s) break;
      }
    }
    if (!broken && cycles > 1) found({Kind::pinched_vertex, links[i].v, -1, cycles});
    i = j;
  }
}

}  // namespace anisocert::geometry
