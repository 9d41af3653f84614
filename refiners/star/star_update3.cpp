#include "refiners/star/star_update3.hpp"

#include "predicates/insphere_perturbed.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace anisocert::refiners::star {

Star3Update insert_into_star3(Star3& star, int v, int k, const std::vector<predicates::Point3<double>>& points,
                              const predicates::Sym3<double>& M) {
  const auto at = [&](int i) -> const predicates::Point3<double>& { return points[static_cast<std::size_t>(i)]; };
  for (const auto& [a, b] : star.open)  // k on or beyond an open face: the hull around v changes
    if (predicates::orientation3(at(v), at(b), at(a), at(k)) != Sign::negative) return Star3Update::recompute;
  std::vector<char> conflict(star.link.size());
  bool any = false;
  for (std::size_t i = 0; i < star.link.size(); ++i) {
    const auto& [a, b, c] = star.link[i];
    conflict[i] = predicates::insphere_perturbed<double>({at(v), at(a), at(b), at(c), at(k)}, {v, a, b, c, k}, M) == Sign::positive;
    any = any || conflict[i];
  }
  if (!any) return Star3Update::unchanged;
  // The kept triangles' directed link edges, and the open ones: a removed triangle's edge (a, b)
  // whose reverse is kept is on the cavity's boundary; one on the open part needs the hull.
  std::set<std::pair<int, int>> kept, open;
  for (std::size_t i = 0; i < star.link.size(); ++i)
    if (!conflict[i])
      for (int j = 0; j < 3; ++j) kept.insert({star.link[i][static_cast<std::size_t>(j)], star.link[i][static_cast<std::size_t>((j + 1) % 3)]});
  for (const auto& [a, b] : star.open) open.insert({a, b});
  std::vector<std::array<int, 3>> link;
  for (std::size_t i = 0; i < star.link.size(); ++i)
    if (!conflict[i]) link.push_back(star.link[i]);
  for (std::size_t i = 0; i < star.link.size(); ++i) {
    if (!conflict[i]) continue;
    for (int j = 0; j < 3; ++j) {
      const int a = star.link[i][static_cast<std::size_t>(j)], b = star.link[i][static_cast<std::size_t>((j + 1) % 3)];
      if (open.count({a, b})) return Star3Update::recompute;
      if (!kept.count({b, a})) continue;  // inside the cavity
      // (v, a, b, k) on the removed side of the face: positively oriented (the cavity is
      // star-shaped from k); anything else is not the configuration Bowyer–Watson assumes.
      if (predicates::orientation3(at(v), at(a), at(b), at(k)) != Sign::positive) return Star3Update::recompute;
      link.push_back({a, b, k});
    }
  }
  if (link.size() == star.link.size() - static_cast<std::size_t>(std::count(conflict.begin(), conflict.end(), 1)))
    return Star3Update::recompute;  // every triangle removed: no boundary (v cannot vanish; not expected)
  star.link = std::move(link);
  return Star3Update::updated;
}

}  // namespace anisocert::refiners::star
