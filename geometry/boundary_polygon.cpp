#include "geometry/boundary_polygon.hpp"

#include <map>
#include <set>

namespace anisocert::geometry {

std::vector<int> boundary_loop(const Mesh<Rational>& m) {
  if (m.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
  std::set<std::pair<int, int>> directed;
  for (std::size_t k = 0; k < m.triangles.size(); ++k) {
    auto t = m.triangles[k];
    const Sign o = predicates::orientation(m.sites[t[0]], m.sites[t[1]], m.sites[t[2]]);
    if (o == Sign::zero) throw std::invalid_argument("triangle " + std::to_string(k) + " is degenerate (its vertices are collinear)");
    if (o == Sign::negative) std::swap(t[1], t[2]);
    for (int i = 0; i < 3; ++i)
      if (!directed.emplace(t[i], t[(i + 1) % 3]).second)
        throw std::invalid_argument("edge (" + std::to_string(t[i]) + ", " + std::to_string(t[(i + 1) % 3]) +
                                    ") is the same side of two triangles: they overlap");
  }
  std::map<int, int> next;  // the boundary: a → b for each directed edge without its reverse
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a}) && !next.emplace(a, b).second)
      throw std::invalid_argument("the boundary of the triangles passes through vertex " + std::to_string(a) +
                                  " twice: it is not one simple loop");
  std::vector<int> loop{next.begin()->first};
  for (int v = next.begin()->second; v != loop.front(); v = next.at(v)) {
    if (!next.count(v)) throw std::invalid_argument("the boundary of the triangles does not close at vertex " + std::to_string(v));
    loop.push_back(v);
    if (loop.size() > next.size()) break;
  }
  if (loop.size() != next.size())
    throw std::invalid_argument("the boundary of the triangles is " + std::string(loop.size() < next.size() ? "more than one loop" : "not a loop") +
                                " (a hole, or several pieces): Labelle and Shewchuk's domain is one simple polygon");
  return loop;
}

Polygon<Rational> without_straight_corners(const Polygon<Rational>& p) {
  Polygon<Rational> polygon;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = p[(i + n - 1) % n];
    const auto& b = p[i];
    const auto& c = p[(i + 1) % n];
    if (predicates::orientation(a, b, c) != Sign::zero || (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0) polygon.push_back(b);
  }
  return polygon;
}

Polygon<Rational> boundary_polygon(const Mesh<Rational>& m) {
  Polygon<Rational> loop;
  for (int v : boundary_loop(m)) loop.push_back(m.sites[static_cast<std::size_t>(v)]);
  const Polygon<Rational> polygon = without_straight_corners(loop);
  if (const auto defect = simplicity_defect(polygon)) throw std::invalid_argument(describe(*defect, polygon, "boundary"));
  return polygon;
}

}  // namespace anisocert::geometry
