#include "oracle/certify/triangulation_check.hpp"

#include "predicates/orientation.hpp"

#include <map>
#include <set>

namespace anisocert::oracle {

using predicates::Point2;

namespace {

std::string pair_text(int a, int b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

std::string list_text(const std::vector<int>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  return s + ")";
}

// A polygon with every turn to the left whose edge direction turns once around: strictly convex.
bool strictly_convex(const std::vector<Point2<Rational>>& p) {
  const std::size_t k = p.size();
  int turns = 0;
  auto half = [](const Rational& dx, const Rational& dy) { return dy > 0 || (dy == 0 && dx > 0) ? 0 : 1; };
  for (std::size_t i = 0; i < k; ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % k];
    const auto& c = p[(i + 2) % k];
    if (predicates::orientation(a, b, c) != Sign::positive) return false;
    if (half(b.x - a.x, b.y - a.y) == 1 && half(c.x - b.x, c.y - b.y) == 0) ++turns;
  }
  return turns == 1;
}

}  // namespace

TriangulationCheck check_triangulation(const std::vector<Point2<Rational>>& sites,
                                       const std::vector<Point2<Rational>>& dom, const std::vector<Cell>& cells) {
  TriangulationCheck t;
  t.checks_run = {"every cell has three or more distinct sites",
                  "every cell is strictly convex and counter-clockwise (exact orientations)",
                  "every interior edge is in exactly two cells, once in each direction",
                  "the unpaired edges tile the edges of Ω counter-clockwise",
                  "every site is a vertex of some cell"};
  std::map<std::pair<int, int>, int> directed;
  std::vector<bool> used(sites.size(), false);
  if (cells.empty()) t.failures.push_back("there is no cell");
  for (const Cell& c : cells) {
    const std::set<int> distinct(c.sites.begin(), c.sites.end());
    if (c.sites.size() < 3 || distinct.size() != c.sites.size()) {
      t.failures.push_back(c.name + " has sites " + list_text(c.sites) + ": fewer than three or a repeated site");
      continue;
    }
    std::vector<Point2<Rational>> p;
    for (int s : c.sites) p.push_back(sites[s]), used[s] = true;
    if (!strictly_convex(p))
      t.failures.push_back(c.name + " with sites " + list_text(c.sites) + " is not strictly convex and counter-clockwise");
    for (std::size_t i = 0; i < c.sites.size(); ++i) ++directed[{c.sites[i], c.sites[(i + 1) % c.sites.size()]}];
  }
  // Unpaired directed edges must lie on ∂Ω, along it; collect them per edge of Ω.
  std::vector<std::map<int, int>> along(dom.size());  // edge k: start site → end site
  for (const auto& [e, count] : directed) {
    const auto [a, b] = e;
    const int back = directed.count({b, a}) ? directed.at({b, a}) : 0;
    if (count > 1) {
      t.failures.push_back("edge " + pair_text(a, b) + " is in " + std::to_string(count) +
                           " cells in the same direction (overlapping cells)");
      continue;
    }
    if (back == 1) continue;
    bool on_boundary = false;
    for (std::size_t k = 0; k < dom.size() && !on_boundary; ++k) {
      const auto& p = dom[k];
      const auto& q = dom[(k + 1) % dom.size()];
      if (predicates::orientation(p, q, sites[a]) != Sign::zero || predicates::orientation(p, q, sites[b]) != Sign::zero)
        continue;
      const Rational dot = (q.x - p.x) * (sites[b].x - sites[a].x) + (q.y - p.y) * (sites[b].y - sites[a].y);
      auto within = [&](const Point2<Rational>& s) {
        const Rational t0 = (q.x - p.x) * (s.x - p.x) + (q.y - p.y) * (s.y - p.y);
        const Rational len = (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
        return t0 >= 0 && t0 <= len;
      };
      if (dot > 0 && within(sites[a]) && within(sites[b])) {
        on_boundary = true;
        if (!along[k].emplace(a, b).second) on_boundary = false;
      }
    }
    if (!on_boundary)
      t.failures.push_back("edge " + pair_text(a, b) + " is in one cell only and does not run counter-clockwise along ∂Ω");
  }
  for (std::size_t k = 0; k < dom.size(); ++k) {
    const auto site_at = [&](const Point2<Rational>& c) {
      for (std::size_t s = 0; s < sites.size(); ++s)
        if (sites[s].x == c.x && sites[s].y == c.y) return static_cast<int>(s);
      return -1;
    };
    const int from = site_at(dom[k]), to = site_at(dom[(k + 1) % dom.size()]);
    int at = from;
    std::size_t steps = 0;
    while (at >= 0 && at != to && along[k].count(at)) at = along[k].at(at), ++steps;
    if (from < 0 || at != to || steps != along[k].size())
      t.failures.push_back("the edges along edge " + std::to_string(k) + " of Ω do not tile it from corner " +
                           std::to_string(k) + " to corner " + std::to_string((k + 1) % dom.size()));
  }
  for (std::size_t s = 0; s < sites.size(); ++s)
    if (!used[s]) t.failures.push_back("site " + std::to_string(s) + " is in no cell");
  t.is_triangulation = t.failures.empty();
  return t;
}


}  // namespace anisocert::oracle
