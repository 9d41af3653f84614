#include "oracle/certify/triangulation_check.hpp"

#include "geometry/polygon.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace anisocert::oracle {

void TriangulationCheck::fail(std::string text) {
  if (failures.size() < described) failures.push_back(std::move(text));
  ++failure_count;
}

CellList triangle_cells(const std::vector<std::array<int, 3>>& triangles) {
  CellList c;
  c.sites.reserve(3 * triangles.size());
  c.begin.reserve(triangles.size() + 1);
  for (const auto& t : triangles) c.add(t.data(), 3);
  c.name = [](std::size_t k) { return "triangle " + std::to_string(k); };
  return c;
}

namespace {

std::pair<int, int> ordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

using predicates::Point2;

std::string pair_text(int a, int b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

// A cell with every turn to the left whose edge direction turns once around: strictly convex.
// (A triangle: its one orientation.)
bool strictly_convex(const EnclosedMesh& m, const int* s, std::size_t k) {
  if (k == 3) return m.orientation(s[0], s[1], s[2]) == Sign::positive;
  const auto& p = m.mesh.sites;
  auto half = [](const Rational& dx, const Rational& dy) { return dy > 0 || (dy == 0 && dx > 0) ? 0 : 1; };
  int turns = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const int a = s[i], b = s[(i + 1) % k], c = s[(i + 2) % k];
    if (m.orientation(a, b, c) != Sign::positive) return false;
    if (half(p[b].x - p[a].x, p[b].y - p[a].y) == 1 && half(p[c].x - p[b].x, p[c].y - p[b].y) == 0) ++turns;
  }
  return turns == 1;
}

// One undirected edge a < b and the cells along it in each direction (a → b forward).
struct EdgeUse {
  int a, b;
  int forward = 0, backward = 0;
  std::size_t cell = 0;  // a cell along it
};

// Every edge of the cells, by a counting sort on the smaller end: linear in the cells.
std::vector<EdgeUse> edge_table(const CellList& cells, std::size_t n) {
  std::vector<std::size_t> start(n + 1, 0);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const std::size_t b = cells.begin[k], len = cells.begin[k + 1] - b;
    for (std::size_t i = 0; i < len; ++i)
      ++start[std::min(cells.sites[b + i], cells.sites[b + (i + 1) % len]) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  struct Slot {
    int other;
    bool forward;
    std::size_t cell;
  };
  std::vector<Slot> slots(start[n]);
  std::vector<std::size_t> at(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const std::size_t b = cells.begin[k], len = cells.begin[k + 1] - b;
    for (std::size_t i = 0; i < len; ++i) {
      const int u = cells.sites[b + i], v = cells.sites[b + (i + 1) % len];
      slots[at[std::min(u, v)]++] = {std::max(u, v), u < v, k};
    }
  }
  std::vector<EdgeUse> edges;
  edges.reserve(slots.size() / 2 + 1);
  for (std::size_t a = 0; a < n; ++a) {
    const auto first = slots.begin() + static_cast<std::ptrdiff_t>(start[a]),
               last = slots.begin() + static_cast<std::ptrdiff_t>(start[a + 1]);
    std::sort(first, last, [](const Slot& x, const Slot& y) { return x.other < y.other; });
    for (auto s = first; s != last; ++s) {
      if (edges.empty() || edges.back().a != static_cast<int>(a) || edges.back().b != s->other)
        edges.push_back({static_cast<int>(a), s->other, 0, 0, s->cell});
      ++(s->forward ? edges.back().forward : edges.back().backward);
    }
  }
  return edges;
}

bool has_edge(const std::vector<EdgeUse>& edges, int u, int v) {
  const int a = std::min(u, v), b = std::max(u, v);
  return std::binary_search(edges.begin(), edges.end(), EdgeUse{a, b},
                            [](const EdgeUse& x, const EdgeUse& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
}

void check_coincident_sites(const EnclosedMesh& m, TriangulationCheck& t) {
  std::vector<int> order(m.approx.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int i) { return std::pair(m.approx[i].x, m.approx[i].y); };
  std::sort(order.begin(), order.end(), [&](int i, int j) { return key(i) < key(j); });
  // Equal rationals have equal nearest doubles: only runs of equal doubles are compared exactly.
  for (std::size_t lo = 0, hi; lo < order.size(); lo = hi) {
    for (hi = lo + 1; hi < order.size() && key(order[hi]) == key(order[lo]); ++hi) {}
    for (std::size_t i = lo; i < hi; ++i)
      for (std::size_t j = i + 1; j < hi; ++j) {
        const auto &p = m.mesh.sites[order[i]], &q = m.mesh.sites[order[j]];
        if (p.x == q.x && p.y == q.y)
          t.fail("sites " + std::to_string(std::min(order[i], order[j])) + " and " + std::to_string(std::max(order[i], order[j])) +
                 " coincide at " + geometry::point_excerpt(p));
      }
  }
}

// The boundary edges must tile ∂Ω counter-clockwise (a domain polygon Ω).
void check_tiles_polygon(const EnclosedMesh& m, const std::vector<std::pair<int, int>>& boundary, TriangulationCheck& t) {
  const auto& sites = m.mesh.sites;
  const auto& dom = m.mesh.domain;
  std::vector<std::map<int, int>> along(dom.size());  // edge k of Ω: start site → end site
  for (const auto& [a, b] : boundary) {
    bool on_boundary = false;
    for (std::size_t k = 0; k < dom.size() && !on_boundary; ++k) {
      const auto& p = dom[k];
      const auto& q = dom[(k + 1) % dom.size()];
      if (predicates::orientation(p, q, sites[a]) != Sign::zero || predicates::orientation(p, q, sites[b]) != Sign::zero)
        continue;
      const Rational dot = (q.x - p.x) * (sites[b].x - sites[a].x) + (q.y - p.y) * (sites[b].y - sites[a].y);
      if (dot > 0 && geometry::on_segment(sites[a], p, q) && geometry::on_segment(sites[b], p, q))
        on_boundary = along[k].emplace(a, b).second;
    }
    if (!on_boundary) {
      t.fail("edge " + pair_text(a, b) + " is in one cell only and does not run counter-clockwise along ∂Ω");
      t.bad_edges.emplace_back(a, b);
    }
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
      t.fail("the edges along edge " + std::to_string(k) + " of Ω do not tile it from corner " + std::to_string(k) +
             " to corner " + std::to_string((k + 1) % dom.size()));
  }
}

// A uniform grid over the boundary edges' boxes (nearest doubles, widened by an ulp): the pairs
// that may meet share a cell; each pair is tested once, in the cell of the low corner of the
// overlap of their boxes. Every test on a pair is exact.
class EdgeGrid {
 public:
  EdgeGrid(const EnclosedMesh& m, const std::vector<std::pair<int, int>>& e) : m_(m), e_(e) {
    for (const auto& [a, b] : e) {
      for (int s : {a, b}) {
        x0_ = std::min(x0_, m.approx[s].x), x1_ = std::max(x1_, m.approx[s].x);
        y0_ = std::min(y0_, m.approx[s].y), y1_ = std::max(y1_, m.approx[s].y);
      }
    }
    side_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(e.size()))));
    cells_.resize(side_ * side_);
    for (std::size_t i = 0; i < e.size(); ++i) {
      const Box b = box(i);
      for (std::size_t cy = cell_y(b.y0); cy <= cell_y(b.y1); ++cy)
        for (std::size_t cx = cell_x(b.x0); cx <= cell_x(b.x1); ++cx) cells_[cy * side_ + cx].push_back(i);
    }
  }
  template <class F>
  void each_pair(F&& f) const {
    for (std::size_t c = 0; c < cells_.size(); ++c)
      for (std::size_t i = 0; i < cells_[c].size(); ++i)
        for (std::size_t j = i + 1; j < cells_[c].size(); ++j) {
          const std::size_t p = cells_[c][i], q = cells_[c][j];
          const Box a = box(p), b = box(q);
          if (a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0) continue;
          if (cell_y(std::max(a.y0, b.y0)) * side_ + cell_x(std::max(a.x0, b.x0)) != c) continue;
          f(p, q);
        }
  }

 private:
  struct Box {
    double x0, x1, y0, y1;
  };
  Box box(std::size_t i) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto &p = m_.approx[e_[i].first], &q = m_.approx[e_[i].second];
    return {std::nextafter(std::min(p.x, q.x), -inf), std::nextafter(std::max(p.x, q.x), inf),
            std::nextafter(std::min(p.y, q.y), -inf), std::nextafter(std::max(p.y, q.y), inf)};
  }
  // Non-decreasing in v, as the bucketing needs. When hi − lo overflows (coordinates near the
  // doubles' limit) f is 0 or NaN, and every v falls in cell 0: one bucket, slower but complete.
  std::size_t cell(double v, double lo, double hi) const {
    if (!(hi > lo)) return 0;
    const double f = (v - lo) / (hi - lo) * static_cast<double>(side_);
    if (!(f > 0)) return 0;
    return f >= static_cast<double>(side_) ? side_ - 1 : static_cast<std::size_t>(f);
  }
  std::size_t cell_x(double v) const { return cell(v, x0_, x1_); }
  std::size_t cell_y(double v) const { return cell(v, y0_, y1_); }
  const EnclosedMesh& m_;
  const std::vector<std::pair<int, int>>& e_;
  double x0_ = INFINITY, x1_ = -INFINITY, y0_ = INFINITY, y1_ = -INFINITY;
  std::size_t side_ = 1;
  std::vector<std::vector<std::size_t>> cells_;
};

// The winding number about p of the directed edges whose index `counts`, by signed crossings of
// the ray from p towards +x (an upward edge a.y <= p.y < b.y with p strictly left of it counts +1,
// a downward one with p strictly right −1), every comparison exact.
int winding_number(const EnclosedMesh& m, const std::vector<std::pair<int, int>>& e, const std::vector<std::size_t>& candidates,
                   int p, const std::function<bool(std::size_t)>& counts) {
  const auto& s = m.mesh.sites;
  int w = 0;
  for (std::size_t i : candidates) {
    if (!counts(i)) continue;
    const auto [a, b] = e[i];
    if (s[a].y <= s[p].y && s[p].y < s[b].y && m.orientation(a, b, p) == Sign::positive) ++w;
    if (s[b].y <= s[p].y && s[p].y < s[a].y && m.orientation(a, b, p) == Sign::negative) --w;
  }
  return w;
}

// The boundary edges form disjoint simple loops, wound so that the cells cover their inside once.
void check_loops(const EnclosedMesh& m, const std::vector<std::pair<int, int>>& e, TriangulationCheck& t) {
  const std::size_t n = m.mesh.sites.size();
  std::vector<int> out(n, -1), in(n, -1);
  bool simple = true;
  // Each site starts at most one boundary edge and ends at most one: slot is out[site] or in[site].
  auto once = [&](std::size_t i, int site, int& slot, const char* how) {
    if (slot >= 0) {
      t.fail("the boundary passes through site " + std::to_string(site) + " twice (edges " +
             pair_text(e[slot].first, e[slot].second) + " and " + pair_text(e[i].first, e[i].second) + " " + how + " it)");
      t.bad_edges.push_back(e[i]);
      simple = false;
    }
    slot = static_cast<int>(i);
  };
  for (std::size_t i = 0; i < e.size(); ++i) {
    once(i, e[i].second, in[e[i].second], "enter");
    once(i, e[i].first, out[e[i].first], "leave");
  }
  const auto& s = m.mesh.sites;
  EdgeGrid(m, e).each_pair([&](std::size_t i, std::size_t j) {
    const auto [a, b] = e[i];
    const auto [c, d] = e[j];
    if (b == c || d == a) {  // consecutive: they may only share that site
      const int shared = b == c ? b : a, u = b == c ? a : b, v = b == c ? d : c;
      if (m.orientation(u, shared, v) != Sign::zero || (s[u].x - s[shared].x) * (s[v].x - s[shared].x) + (s[u].y - s[shared].y) * (s[v].y - s[shared].y) <= 0)
        return;
    } else if (geometry::segments_meet(s[a], s[b], s[c], s[d]) == geometry::Meeting::none) {
      return;
    }
    t.fail("boundary edges " + pair_text(a, b) + " and " + pair_text(c, d) + " meet: the boundary is not a set of disjoint simple loops");
    t.bad_edges.push_back(e[i]), t.bad_edges.push_back(e[j]);
    simple = false;
  });
  if (!simple) return;  // the winding test needs disjoint simple loops
  // The loops, and horizontal strips of the edges for the winding numbers.
  std::vector<int> loop_of(e.size(), -1);
  std::vector<int> loop_start;
  for (std::size_t i = 0; i < e.size() && simple; ++i) {
    if (loop_of[i] >= 0) continue;
    const int id = static_cast<int>(loop_start.size());
    loop_start.push_back(static_cast<int>(i));
    // Each site has at most one boundary edge in and one out here; the chain from edge i comes back
    // to it unless the boundary is open (edges in the same direction twice leave it unbalanced).
    for (int j = static_cast<int>(i); loop_of[j] < 0;) {
      loop_of[j] = id;
      const int next = out[e[j].second];
      if (next < 0) {
        t.fail("the boundary does not close: no boundary edge leaves site " + std::to_string(e[j].second));
        t.bad_edges.push_back(e[j]);
        simple = false;
        break;
      }
      j = next;
    }
  }
  if (!simple) return;
  double y0 = INFINITY, y1 = -INFINITY;
  for (const auto& p : m.approx) y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  const std::size_t strips = std::max<std::size_t>(1, e.size() / 8);
  // The approximations are monotone (EnclosedMesh::approx), so an edge whose exact height range holds p's has
  // an approximate range holding p's approximate height: it lies in p's strip.
  auto strip = [&](double y) {
    const double f = y1 > y0 ? (y - y0) / (y1 - y0) * static_cast<double>(strips) : 0;
    return f <= 0 ? std::size_t(0) : std::min(strips - 1, static_cast<std::size_t>(f));
  };
  std::vector<std::vector<std::size_t>> in_strip(strips);
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double a = m.approx[e[i].first].y, b = m.approx[e[i].second].y;
    for (std::size_t k = strip(std::min(a, b)); k <= strip(std::max(a, b)); ++k) in_strip[k].push_back(i);
  }
  for (std::size_t l = 0; l < loop_start.size(); ++l) {
    // The loop's orientation at its lowest (then leftmost) site, which is a convex corner.
    int low = e[loop_start[l]].first;
    for (int j = out[low]; e[j].second != e[loop_start[l]].first; j = out[e[j].second]) {
      const int v = e[j].second;
      if (s[v].y < s[low].y || (s[v].y == s[low].y && s[v].x < s[low].x)) low = v;
    }
    const bool counter_clockwise = m.orientation(e[in[low]].first, low, e[out[low]].second) == Sign::positive;
    const int w = winding_number(m, e, in_strip[strip(m.approx[low].y)], low,
                                 [&](std::size_t i) { return loop_of[i] != static_cast<int>(l); });
    if (w != (counter_clockwise ? 0 : 1)) {
      t.fail(counter_clockwise ? "the boundary loop through site " + std::to_string(low) + " lies inside " +
                                     std::to_string(w) + " other part(s) of the mesh: the cells overlap there"
                               : "the hole bounded by the clockwise loop through site " + std::to_string(low) +
                                     " is not inside exactly one part of the mesh (winding number " + std::to_string(w) + ")");
      t.bad_edges.push_back(e[out[low]]);
    }
  }
}

}  // namespace

std::vector<std::pair<int, int>> unique_edges(const CellList& cells, std::size_t site_count) {
  std::vector<std::pair<int, int>> e;
  for (const EdgeUse& u : edge_table(cells, site_count)) e.emplace_back(u.a, u.b);
  return e;
}

TriangulationCheck check_triangulation(const EnclosedMesh& m, const CellList& cells, std::size_t described) {
  TriangulationCheck t;
  t.described = described;
  const bool polygon = !m.mesh.domain.empty();
  t.checks_run = {"no two sites coincide",
                  "every cell has three or more distinct sites",
                  "every cell is strictly convex and counter-clockwise (exact orientations)",
                  "every interior edge is in exactly two cells, once in each direction"};
  if (polygon) {
    t.checks_run.push_back("the unpaired edges tile the edges of Ω counter-clockwise");
  } else {
    t.checks_run.push_back("the unpaired edges form disjoint simple loops, each covered once on its inside");
    if (!m.mesh.edges.empty())
      t.checks_run.push_back("the unpaired edges are edges of the file, and every edge of the file is an edge of the cells");
  }
  t.checks_run.push_back("every site is a vertex of some cell");
  const std::size_t n = m.mesh.sites.size();
  if (cells.size() == 0) t.fail("there is no cell");
  check_coincident_sites(m, t);
  std::vector<bool> used(n, false);
  std::vector<bool> bad_cell(cells.size(), false);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int* s = cells.sites.data() + cells.begin[k];
    const std::size_t len = cells.begin[k + 1] - cells.begin[k];
    for (std::size_t i = 0; i < len; ++i) used[s[i]] = true;
    bool distinct = len >= 3;
    for (std::size_t i = 0; i < len && distinct; ++i)
      for (std::size_t j = i + 1; j < len; ++j) distinct = distinct && s[i] != s[j];
    std::string sites_text;
    auto list = [&] {
      std::string l = "(";
      for (std::size_t i = 0; i < len; ++i) l += (i ? ", " : "") + std::to_string(s[i]);
      return l + ")";
    };
    if (!distinct) {
      t.fail(cells.name(k) + " has sites " + list() + ": fewer than three or a repeated site");
      bad_cell[k] = true;
    } else if (!strictly_convex(m, s, len)) {
      t.fail(cells.name(k) + " with sites " + list() + " is not strictly convex and counter-clockwise");
      bad_cell[k] = true;
    }
  }
  const std::vector<EdgeUse> edges = edge_table(cells, n);
  std::vector<std::pair<int, int>> boundary;  // the unpaired directed edges
  for (const EdgeUse& u : edges) {
    if (u.forward > 1 || u.backward > 1) {
      t.fail("edge " + pair_text(u.a, u.b) + " is in " + std::to_string(std::max(u.forward, u.backward)) +
             " cells in the same direction (overlapping cells)");
      t.bad_edges.emplace_back(u.a, u.b);
      bad_cell[u.cell] = true;
    } else if (u.forward + u.backward == 1) {
      boundary.push_back(u.forward ? std::pair(u.a, u.b) : std::pair(u.b, u.a));
    }
  }
  if (polygon) {
    check_tiles_polygon(m, boundary, t);
  } else {
    if (!m.mesh.edges.empty()) {
      std::vector<std::pair<int, int>> declared;
      for (std::size_t k = 0; k < m.mesh.edges.size(); ++k) {
        const auto [a, b] = m.mesh.edges[k];
        declared.push_back(ordered(a, b));
        if (!has_edge(edges, a, b)) {
          t.fail("edge " + std::to_string(k) + " " + pair_text(a, b) +
                 " of the file is not an edge of the cells (the file declares edges where no triangle is: a surface left out?)");
          t.bad_edges.emplace_back(a, b);
        }
      }
      std::sort(declared.begin(), declared.end());
      for (const auto& [a, b] : boundary)
        if (!std::binary_search(declared.begin(), declared.end(), ordered(a, b))) {
          t.fail("edge " + pair_text(a, b) +
                 " bounds the union of the cells but is not an edge of the file: the cells do not cover exactly the declared domain");
          t.bad_edges.emplace_back(a, b);
        }
    }
    check_loops(m, boundary, t);
  }
  for (std::size_t s = 0; s < n; ++s)
    if (!used[s]) t.fail("site " + std::to_string(s) + " is in no cell");
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (bad_cell[k]) t.bad_cells.push_back(static_cast<int>(k));
  t.is_triangulation = t.failure_count == 0;
  return t;
}

}  // namespace anisocert::oracle
