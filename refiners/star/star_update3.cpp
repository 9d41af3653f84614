#include "refiners/star/star_update3.hpp"

#include "predicates/insphere_perturbed.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <utility>

namespace anisocert::refiners::star {

Star3Update insert_into_star3(Star3& star, int v, int k, const std::vector<predicates::Point3<double>>& points,
                              const predicates::Sym3<double>& M) {
  using Edge = std::pair<int, int>;
  const auto at = [&](int i) -> const predicates::Point3<double>& { return points[static_cast<std::size_t>(i)]; };
  const auto edge = [](const std::array<int, 3>& t, int j) {
    return Edge{t[static_cast<std::size_t>(j)], t[static_cast<std::size_t>((j + 1) % 3)]};
  };
  // Real tetrahedra in conflict: k inside their perturbed M-sphere.
  std::vector<char> conflict(star.link.size());
  bool any = false;
  for (std::size_t i = 0; i < star.link.size(); ++i) {
    const auto& [a, b, c] = star.link[i];
    conflict[i] = predicates::insphere_perturbed<double>({at(v), at(a), at(b), at(c), at(k)}, {v, a, b, c, k}, M) == Sign::positive;
    any = any || conflict[i];
  }
  // Directed link edges with their triangles, sorted (for the open faces' owners and the kept side).
  std::vector<std::pair<Edge, std::size_t>> owner;
  owner.reserve(3 * star.link.size());
  for (std::size_t i = 0; i < star.link.size(); ++i)
    for (int j = 0; j < 3; ++j) owner.push_back({edge(star.link[i], j), i});
  std::sort(owner.begin(), owner.end());
  const auto owner_of = [&](const Edge& e) -> const std::size_t* {
    const auto it = std::lower_bound(owner.begin(), owner.end(), std::pair<Edge, std::size_t>{e, 0});
    return it != owner.end() && it->first == e ? &it->second : nullptr;
  };
  // Ghosts (the open faces, v on the hull): in conflict when k is strictly beyond the face's
  // plane, or on it inside the face's circle, i.e. in conflict with the tetrahedron behind it
  // (every M-sphere through v, a, b meets the plane in that one circle).
  std::vector<char> ghost(star.open.size());
  for (std::size_t g = 0; g < star.open.size(); ++g) {
    const auto [a, b] = star.open[g];
    const Sign side = predicates::orientation3(at(v), at(b), at(a), at(k));
    const std::size_t* behind = owner_of({a, b});
    if (!behind) return Star3Update::recompute;  // not a star's open face: wrap again
    ghost[g] = side == Sign::positive || (side == Sign::zero && conflict[*behind]);
    any = any || ghost[g];
  }
  if (!any) return Star3Update::unchanged;
  const auto kept = [&](const Edge& e) {
    const std::size_t* i = owner_of(e);
    return i && !conflict[*i];
  };
  const auto open_kept = [&](const Edge& e) {
    for (std::size_t g = 0; g < star.open.size(); ++g)
      if (!ghost[g] && star.open[g][0] == e.first && star.open[g][1] == e.second) return true;
    return false;
  };
  std::vector<std::array<int, 3>> link;
  for (std::size_t i = 0; i < star.link.size(); ++i)
    if (!conflict[i]) link.push_back(star.link[i]);
  // The cavity's boundary faces at v, each joined to k: a removed tetrahedron's face facing a kept
  // one or a kept ghost (the hull stays there), and a removed ghost's face facing a kept
  // tetrahedron. Each new tetrahedron must be positively oriented (the cavity is star-shaped
  // from k); anything else is not the configuration Bowyer–Watson assumes: wrap again.
  const auto join = [&](int a, int b) {
    if (predicates::orientation3(at(v), at(a), at(b), at(k)) != Sign::positive) return false;
    link.push_back({a, b, k});
    return true;
  };
  for (std::size_t i = 0; i < star.link.size(); ++i) {
    if (!conflict[i]) continue;
    for (int j = 0; j < 3; ++j) {
      const auto [a, b] = edge(star.link[i], j);
      if ((kept({b, a}) || open_kept({a, b})) && !join(a, b)) return Star3Update::recompute;
    }
  }
  for (std::size_t g = 0; g < star.open.size(); ++g) {
    const auto [a, b] = star.open[g];
    if (ghost[g] && !conflict[*owner_of({a, b})] && !join(b, a)) return Star3Update::recompute;
  }
  // The new link's open edges: those whose reverse no triangle has. Each directed edge at most
  // once (a disk or a sphere around v), or the update is not what Bowyer–Watson assumes.
  std::vector<Edge> edges;
  edges.reserve(3 * link.size());
  for (const auto& t : link)
    for (int j = 0; j < 3; ++j) edges.push_back(edge(t, j));
  std::sort(edges.begin(), edges.end());
  if (link.empty() || std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return Star3Update::recompute;
  std::vector<std::array<int, 2>> open;
  for (const auto& [a, b] : edges)
    if (!std::binary_search(edges.begin(), edges.end(), Edge{b, a})) open.push_back({a, b});
  star.link = std::move(link);
  star.open = std::move(open);
  return Star3Update::updated;
}

}  // namespace anisocert::refiners::star
