#include "refiners/star/star_update3.hpp"

#include "predicates/insphere_perturbed.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace anisocert::refiners::star {

Star3Update insert_into_star3(Star3& star, int v, int k, const std::vector<predicates::Point3<double>>& points,
                              const predicates::Sym3<double>& M) {
  const auto at = [&](int i) -> const predicates::Point3<double>& { return points[static_cast<std::size_t>(i)]; };
  const auto edge = [](const std::array<int, 3>& t, int j) {
    return std::pair<int, int>{t[static_cast<std::size_t>(j)], t[static_cast<std::size_t>((j + 1) % 3)]};
  };
  // Real tetrahedra in conflict: k inside their perturbed M-sphere.
  std::vector<char> conflict(star.link.size());
  std::map<std::pair<int, int>, std::size_t> owner;  // directed link edge → its triangle
  for (std::size_t i = 0; i < star.link.size(); ++i) {
    const auto& [a, b, c] = star.link[i];
    conflict[i] = predicates::insphere_perturbed<double>({at(v), at(a), at(b), at(c), at(k)}, {v, a, b, c, k}, M) == Sign::positive;
    for (int j = 0; j < 3; ++j) owner[edge(star.link[i], j)] = i;
  }
  // Ghosts (the open faces, v on the hull): in conflict when k is strictly beyond the face's
  // plane, or on it inside the face's circle, i.e. in conflict with the tetrahedron behind it
  // (every M-sphere through v, a, b meets the plane in that one circle).
  std::vector<char> ghost(star.open.size());
  for (std::size_t g = 0; g < star.open.size(); ++g) {
    const auto [a, b] = star.open[g];
    const Sign side = predicates::orientation3(at(v), at(b), at(a), at(k));
    ghost[g] = side == Sign::positive || (side == Sign::zero && conflict[owner.at({a, b})]);
  }
  if (std::none_of(conflict.begin(), conflict.end(), [](char c) { return c != 0; }) &&
      std::none_of(ghost.begin(), ghost.end(), [](char c) { return c != 0; }))
    return Star3Update::unchanged;
  std::set<std::pair<int, int>> kept, open_kept, open_removed;
  for (std::size_t i = 0; i < star.link.size(); ++i)
    if (!conflict[i])
      for (int j = 0; j < 3; ++j) kept.insert(edge(star.link[i], j));
  for (std::size_t g = 0; g < star.open.size(); ++g) (ghost[g] ? open_removed : open_kept).insert({star.open[g][0], star.open[g][1]});
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
      if ((kept.count({b, a}) || open_kept.count({a, b})) && !join(a, b)) return Star3Update::recompute;
    }
  }
  for (const auto& [a, b] : open_removed)
    if (!conflict[owner.at({a, b})] && !join(b, a)) return Star3Update::recompute;
  // The new link's open edges: those whose reverse no triangle has. Each directed edge at most
  // once (a disk or a sphere around v), or the update is not what Bowyer–Watson assumes.
  std::set<std::pair<int, int>> edges;
  for (const auto& t : link)
    for (int j = 0; j < 3; ++j)
      if (!edges.insert(edge(t, j)).second) return Star3Update::recompute;
  if (link.empty()) return Star3Update::recompute;
  std::vector<std::array<int, 2>> open;
  for (const auto& [a, b] : edges)
    if (!edges.count({b, a})) open.push_back({a, b});
  star.link = std::move(link);
  star.open = std::move(open);
  return Star3Update::updated;
}

}  // namespace anisocert::refiners::star
