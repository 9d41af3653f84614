// The geometric dual of D|Ω (LS §5) and the exact decision whether it is a triangulation
// (polygonalization) of Ω (BWY §3.2.1), and the Theorem 7 verdict (LS Theorem 7).
//
// The check is simpler than the diagram it checks (DESIGN.md § Certificates): with every dual
// cell strictly convex and counter-clockwise, and the cells' directed edges cancelling in pairs
// except for edges that tile ∂Ω counter-clockwise, the boundary of the 2-chain of cells is ∂Ω,
// so every point of Ω off the edges is covered exactly once (its coverage is the winding number
// of ∂Ω about it) and no point outside is covered.
#include "oracle/diagram_build.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace anisocert::oracle::build {

namespace {

std::string pair_text(int a, int b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

std::string list_text(const std::vector<int>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  return s + ")";
}

int left_site_of(const Diagram& d, int h) {
  const HalfEdge& e = d.half_edges[h];
  return d.cycles[e.cycle].site;
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

void Builder::build_dual() {
  for (int n = 0; n < static_cast<int>(d_.nodes.size()); ++n) {
    const Node& node = d_.nodes[n];
    if (node.sites.size() < 3) continue;
    const auto& gs = germs_[n];
    if (gs.empty()) continue;  // a vertex of D|Ω on ∂Ω whose arcs all leave Ω at once
    // The sector after germ i (counter-clockwise) is on the left of germ i's outgoing half-edge;
    // after the incoming boundary piece lies the outside of Ω.
    std::vector<int> owners;
    std::size_t start = 0;
    for (std::size_t i = 0; i < gs.size(); ++i)
      if (gs[i].outgoing < 0) start = (i + 1) % gs.size();
    for (std::size_t k = 0; k < gs.size(); ++k) {
      const Germ& g = gs[(start + k) % gs.size()];
      if (g.outgoing >= 0) owners.push_back(left_site_of(d_, g.outgoing));
    }
    const bool interior = std::all_of(gs.begin(), gs.end(), [](const Germ& g) { return g.outgoing >= 0; });
    if (interior)  // a cycle: start at the least site, for a canonical listing
      std::rotate(owners.begin(), std::min_element(owners.begin(), owners.end()), owners.end());
    std::set<int> distinct(owners.begin(), owners.end());
    (owners.size() == 3 && distinct.size() == 3 ? d_.dual_triangles : d_.dual_polygons).push_back({n, owners});
  }
}

void Builder::check_triangulation() {
  TriangulationCheck& t = d_.dual_check;
  const auto& sites = d_.input.sites;
  const auto& dom = d_.input.domain;
  t.checks_run = {"every dual cell has three or more distinct sites",
                  "every dual cell is strictly convex and counter-clockwise (exact orientations)",
                  "every interior dual edge is in exactly two cells, once in each direction",
                  "the unpaired dual edges tile the edges of Ω counter-clockwise",
                  "every site is a vertex of some cell"};
  std::map<std::pair<int, int>, int> directed;
  std::vector<bool> used(sites.size(), false);
  std::vector<const DualCell*> cells;
  for (const auto& c : d_.dual_triangles) cells.push_back(&c);
  for (const auto& c : d_.dual_polygons) cells.push_back(&c);
  if (cells.empty()) t.failures.push_back("the diagram has no Voronoi vertex in Ω, so its dual has no cell");
  for (const DualCell* c : cells) {
    const std::set<int> distinct(c->sites.begin(), c->sites.end());
    if (c->sites.size() < 3 || distinct.size() != c->sites.size()) {
      t.failures.push_back("the dual cell of vertex " + std::to_string(c->vertex) + " has sites " + list_text(c->sites) +
                           ": fewer than three or a repeated site");
      continue;
    }
    std::vector<Point2<Rational>> p;
    for (int s : c->sites) p.push_back(sites[s]), used[s] = true;
    if (!strictly_convex(p))
      t.failures.push_back("the dual cell of vertex " + std::to_string(c->vertex) + " with sites " + list_text(c->sites) +
                           " is not strictly convex and counter-clockwise");
    for (std::size_t i = 0; i < c->sites.size(); ++i) ++directed[{c->sites[i], c->sites[(i + 1) % c->sites.size()]}];
  }
  // Unpaired directed edges must lie on ∂Ω, along it; collect them per edge of Ω.
  std::vector<std::map<int, int>> along(dom.size());  // edge k: start site → end site
  for (const auto& [e, count] : directed) {
    const auto [a, b] = e;
    const int back = directed.count({b, a}) ? directed.at({b, a}) : 0;
    if (count > 1) {
      t.failures.push_back("dual edge " + pair_text(a, b) + " is in " + std::to_string(count) +
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
      t.failures.push_back("dual edge " + pair_text(a, b) + " is in one cell only and does not run counter-clockwise along ∂Ω");
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
      t.failures.push_back("the dual edges along edge " + std::to_string(k) + " of Ω do not tile it from corner " +
                           std::to_string(k) + " to corner " + std::to_string((k + 1) % dom.size()));
  }
  for (std::size_t s = 0; s < sites.size(); ++s)
    if (!used[s]) t.failures.push_back("site " + std::to_string(s) + " is in no dual cell");
  t.is_triangulation = t.failures.empty();
}

void Builder::check_theorem7() {
  Theorem7& th = d_.theorem7;
  const auto& sites = d_.input.sites;
  const auto& dom = d_.input.domain;
  std::vector<int> corner_site(dom.size(), -1);
  for (std::size_t k = 0; k < dom.size(); ++k) {
    for (std::size_t s = 0; s < sites.size(); ++s)
      if (sites[s].x == dom[k].x && sites[s].y == dom[k].y) corner_site[k] = static_cast<int>(s);
    if (corner_site[k] < 0) th.reasons.push_back("corner " + std::to_string(k) + " of Ω is not a site");
  }
  for (std::size_t a = 0; a < d_.arcs.size(); ++a)
    for (int k : d_.arcs[a].cut_by_edges) {
      const int p = corner_site[k], q = corner_site[(k + 1) % dom.size()];
      if (std::minmax(p, q) != std::minmax(d_.arcs[a].v, d_.arcs[a].w))
        th.reasons.push_back("arc " + std::to_string(a) + " of sites " + pair_text(d_.arcs[a].v, d_.arcs[a].w) +
                             " is cut by edge " + std::to_string(k) + " of Ω, whose endpoints are not its sites");
    }
  for (std::size_t a = 0; a < d_.arcs.size(); ++a)
    if (!d_.arcs[a].wedged) th.reasons.push_back("arc " + std::to_string(a) + " is not wedged");
  for (std::size_t n = 0; n < d_.nodes.size(); ++n)
    if (d_.nodes[n].sites.size() >= 2 && !d_.nodes[n].wedged)
      th.reasons.push_back("vertex " + std::to_string(n) + " is not wedged");
  th.preconditions_hold = th.reasons.empty();
  th.disagreement = th.preconditions_hold && !d_.dual_check.is_triangulation;
}

}  // namespace anisocert::oracle::build
