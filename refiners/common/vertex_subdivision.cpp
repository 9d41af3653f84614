#include "refiners/common/vertex_subdivision.hpp"

#include "refiners/common/box_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace anisocert::refiners::common {
namespace {

using FI = FilterInterval;

// Where a node is split, as a fraction of its width: not ½, so that the split lines are not the
// simple dyadic lines (x = ¾, …) on which the vertices of symmetric sites lie. A vertex on a
// leaf's side cannot be placed in or out of the leaf by boxes, and the leaf stays unresolved.
constexpr double split_ratio = 0.5 + 0x1p-6 + 0x1p-11 + 0x1p-19;

Box2<FI> interval_box(const Box& b) { return {FI(b.x0, b.x1), FI(b.y0, b.y1)}; }

// Whether the vertex lies in the closed box b (a search may certify a point just beyond its box,
// where other sites can be nearer); nothing when undecided.
std::optional<bool> in_closed_box(const Trio& t, const VertexBox& v, const Box& b) {
  const auto& x = v.box.x;
  const auto& y = v.box.y;
  if (x.lo >= b.x0 && x.hi <= b.x1 && y.lo >= b.y0 && y.hi <= b.y1) return true;
  if (x.hi < b.x0 || x.lo > b.x1 || y.hi < b.y0 || y.lo > b.y1) return false;
  const CertifiedPoint p(t, v);
  for (int side = 0; side < 4; ++side) {
    const auto s = sign_at<1>({&p}, [&](const auto& P, auto of) {
      switch (side) {
        case 0: return P[0].x - of(b.x0);
        case 1: return of(b.x1) - P[0].x;
        case 2: return P[0].y - of(b.y0);
        default: return of(b.y1) - P[0].y;
      }
    });
    if (!s) return std::nullopt;
    if (*s == Sign::negative) return false;
  }
  return true;
}

}  // namespace

VertexSubdivision::VertexSubdivision(const Box& R, double min_width, const Domain* omega) : min_width_(min_width), omega_(omega) {
  if (!(R.x0 < R.x1 && R.y0 < R.y1 && min_width > 0)) throw std::invalid_argument("VertexSubdivision: an empty box or min_width <= 0");
  nodes_.push_back({R, {}, INFINITY, -1, {}, false, {}});
}

std::vector<int> VertexSubdivision::candidates_in(const Box& b, const std::vector<int>& from, int extra, double& U) const {
  std::vector<int> all = from;
  if (extra >= 0) all.push_back(extra);
  std::vector<Bounds> range(all.size());
  U = INFINITY;
  for (std::size_t i = 0; i < all.size(); ++i) {
    range[i] = squared_distance_bounds(sites_[static_cast<std::size_t>(all[i])], b);
    U = std::min(U, range[i].hi);
  }
  std::vector<int> kept;
  std::vector<double> centre;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!(range[i].lo > U)) kept.push_back(all[i]), centre.push_back(range[i].lo / 2 + range[i].hi / 2);
  if (kept.size() <= 3) return kept;
  // Then against the two sites likeliest nearest in b (least midpoint of their ranges): u is left
  // out when one of them is strictly nearer everywhere in b. The nearest site at a point is never
  // left out, since no site is strictly nearer there.
  std::array<std::size_t, 2> best{0, 1};
  if (centre[1] < centre[0]) std::swap(best[0], best[1]);
  for (std::size_t i = 2; i < kept.size(); ++i)
    if (centre[i] < centre[best[0]]) best = {i, best[0]};
    else if (centre[i] < centre[best[1]]) best[1] = i;
  std::vector<int> left;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const MetricSite& u = sites_[static_cast<std::size_t>(kept[i])];
    const bool farther = std::any_of(best.begin(), best.end(), [&](std::size_t j) {
      return j != i && squared_distance_difference_bounds(u, sites_[static_cast<std::size_t>(kept[j])], b).lo > 0;
    });
    if (!farther) left.push_back(kept[i]);
  }
  return left;
}

int VertexSubdivision::intern(const std::array<int, 3>& trio, const VertexBox& box) {
  std::vector<int>& same_trio = by_trio_[trio];
  for (int id : same_trio) {
    const auto same = same_vertex(vertices_[static_cast<std::size_t>(id)].box, box);
    if (!same) return -1;
    if (*same) {
      ++vertices_[static_cast<std::size_t>(id)].holders;
      return id;
    }
  }
  const int id = static_cast<int>(vertices_.size());
  vertices_.push_back({trio, box, 1});
  same_trio.push_back(id);
  created_.push_back(id);
  return id;
}

VertexSubdivision::Resolution VertexSubdivision::resolve(int n, bool small, const std::vector<TrioSearch>& inherited) {
  const std::vector<int> c = nodes_[static_cast<std::size_t>(n)].candidates;
  const Box b = nodes_[static_cast<std::size_t>(n)].box;
  // A complete search over a box that holds b found every point of the trio in b (and the checks
  // below keep those in b): the leaf's own from before this insertion, or an ancestor's. The same
  // trio is searched again and again otherwise: as a leaf takes a new candidate and is halved, its
  // halves hold the trios it held (302,120 searches of 23,210 trios on a FreeFem metric).
  const std::vector<TrioSearch> before = std::move(nodes_[static_cast<std::size_t>(n)].searched);
  nodes_[static_cast<std::size_t>(n)].searched.clear();
  const auto search_of = [&](const std::array<int, 3>& t, const Trio& trio) {
    for (const auto* list : {&before, &inherited})
      for (const TrioSearch& s : *list)
        if (s.trio == t) return s.search;
    return vertices_in(trio, interval_box(b));
  };
  std::vector<std::pair<std::array<int, 3>, VertexBox>> found;
  bool degree_4 = false;  // a point where a fourth candidate may be as near as three
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j)
      for (std::size_t l = j + 1; l < c.size(); ++l) {
        std::array<int, 3> t{c[i], c[j], c[l]};
        std::sort(t.begin(), t.end());
        const Trio trio{sites_[static_cast<std::size_t>(t[0])], sites_[static_cast<std::size_t>(t[1])], sites_[static_cast<std::size_t>(t[2])]};
        // A trio one of whose sites another candidate beats all over the box has no vertex there.
        const auto beaten = [&](int a) {
          return std::any_of(c.begin(), c.end(), [&](int w) {
            return w != t[0] && w != t[1] && w != t[2] &&
                   squared_distance_difference_bounds(sites_[static_cast<std::size_t>(w)], sites_[static_cast<std::size_t>(a)], b).hi < 0;
          });
        };
        if (c.size() > 3 && std::any_of(t.begin(), t.end(), beaten)) continue;
        const VertexSearch search = search_of(t, trio);
        if (!search.complete) return small ? Resolution::unresolved : Resolution::split;
        nodes_[static_cast<std::size_t>(n)].searched.push_back({t, search});
        for (const VertexBox& v : search.vertices) {
          const auto inside = in_closed_box(trio, v, b);
          if (!inside) return Resolution::unresolved;
          if (!*inside) continue;
          const CertifiedPoint P(trio, v);
          bool vertex = true;
          for (int u : c) {
            if (u == t[0] || u == t[1] || u == t[2]) continue;
            const auto farther = sign_at<1>({&P}, [&](const auto& X, auto of) {
              const auto d2 = [&](const MetricSite& w) {
                const auto dx = X[0].x - of(w.p.x), dy = X[0].y - of(w.p.y);
                return of(w.M.m11) * (dx * dx) + of(2 * w.M.m12) * (dx * dy) + of(w.M.m22) * (dy * dy);
              };
              return d2(sites_[static_cast<std::size_t>(u)]) - d2(trio[0]);
            });
            if (!farther || *farther == Sign::zero) degree_4 = true;
            else if (*farther == Sign::negative) vertex = false;
          }
          if (vertex) found.emplace_back(t, v);
        }
      }
  if (degree_4) return Resolution::split;
  std::vector<int> held;
  for (const auto& [t, v] : found) {
    const int id = intern(t, v);
    if (id < 0) {
      nodes_[static_cast<std::size_t>(n)].vertices = std::move(held);
      return Resolution::unresolved;
    }
    held.push_back(id);
  }
  nodes_[static_cast<std::size_t>(n)].vertices = std::move(held);
  return Resolution::resolved;
}

void VertexSubdivision::settle(int n, bool first_small, const std::vector<TrioSearch>& inherited) {
  const std::vector<int> cands = nodes_[static_cast<std::size_t>(n)].candidates;
  if (cands.size() < 3) {
    nodes_[static_cast<std::size_t>(n)].searched.clear();
    return;
  }
  const Box b = nodes_[static_cast<std::size_t>(n)].box;
  if (omega_ && omega_->contains(b) == std::optional<bool>(false)) return;  // outside closed Ω
  // Small: no wider than 2⁻⁴ of the least distance between two candidates. Three candidates
  // whose search is undecided tie along a curve (VertexSearch::singular), or nearly: their
  // equidistant points are double points, or so ill-conditioned that doubles cannot isolate them
  // (three sites on the line x = ½ of the linear field, one of them an ulp off it). Such a leaf is
  // halved only until it is small, so that its centre is near the curve, not down to min_width
  // along all of the curve, which took the tree to its bound on the linear field. A small leaf of up
  // to six candidates that splitting has not separated is resolved trio by trio, once: when that
  // finds a fourth candidate as near (a vertex of degree 4), its halves are split as before, down
  // to min_width, without the trios' signs at every level.
  bool small = false;
  if (cands.size() <= 6) {
    double gap = INFINITY;
    for (std::size_t i = 0; i < cands.size(); ++i)
      for (std::size_t j = i + 1; j < cands.size(); ++j) {
        const auto& p = sites_[static_cast<std::size_t>(cands[i])].p;
        const auto& q = sites_[static_cast<std::size_t>(cands[j])].p;
        gap = std::min(gap, std::hypot(p.x - q.x, p.y - q.y));
      }
    small = std::max(b.x1 - b.x0, b.y1 - b.y0) <= 0x1p-4 * gap;
  }
  if (cands.size() == 3 || (small && first_small)) {
    const Resolution r = resolve(n, small, inherited);
    if (r == Resolution::resolved) return;
    if (r == Resolution::unresolved) {
      nodes_[static_cast<std::size_t>(n)].unresolved = true;
      ++unresolved_leaves_;
      return;
    }
  }
  if (std::max(b.x1 - b.x0, b.y1 - b.y0) <= min_width_ || full()) {
    nodes_[static_cast<std::size_t>(n)].unresolved = true;
    ++unresolved_leaves_;
    return;
  }
  // Halved across its longer side as the candidates' metrics measure it: the cells of an
  // anisotropic field are long and thin, and boxes cut to their shape separate them in far fewer
  // leaves than squares (the linear field's cells near y = ½ are a hundred times wider than high).
  double across_x = 0, across_y = 0;
  for (int u : nodes_[static_cast<std::size_t>(n)].candidates) {
    const auto& M = sites_[static_cast<std::size_t>(u)].M;
    across_x += M.m11, across_y += M.m22;
  }
  const bool along_x = across_x * (b.x1 - b.x0) * (b.x1 - b.x0) >= across_y * (b.y1 - b.y0) * (b.y1 - b.y0);
  const int c = static_cast<int>(nodes_.size());
  nodes_.resize(nodes_.size() + 2);
  const double mx = b.x0 + (b.x1 - b.x0) * split_ratio, my = b.y0 + (b.y1 - b.y0) * split_ratio;
  const std::array<Box, 2> halves = along_x ? std::array<Box, 2>{Box{b.x0, mx, b.y0, b.y1}, Box{mx, b.x1, b.y0, b.y1}}
                                            : std::array<Box, 2>{Box{b.x0, b.x1, b.y0, my}, Box{b.x0, b.x1, my, b.y1}};
  for (int i = 0; i < 2; ++i) {
    const auto h = halves[static_cast<std::size_t>(i)];
    double U;
    std::vector<int> kept = candidates_in(h, nodes_[static_cast<std::size_t>(n)].candidates, -1, U);
    nodes_[static_cast<std::size_t>(c + i)] = {h, std::move(kept), U, -1, {}, false, {}};
  }
  nodes_[static_cast<std::size_t>(n)].child = c;
  nodes_[static_cast<std::size_t>(n)].candidates.clear();
  // Its searches go down to the halves (a local: settle grows nodes_), then the ancestors'.
  std::vector<TrioSearch> down = std::move(nodes_[static_cast<std::size_t>(n)].searched);
  nodes_[static_cast<std::size_t>(n)].searched.clear();
  down.insert(down.end(), inherited.begin(), inherited.end());
  for (int i = 0; i < 2; ++i) settle(c + i, !small, down);
  bound_by_children(n);
}

void VertexSubdivision::bound_by_children(int n) {
  Node& node = nodes_[static_cast<std::size_t>(n)];
  double greatest = 0;
  for (int i = 0; i < 2; ++i) greatest = std::max(greatest, nodes_[static_cast<std::size_t>(node.child + i)].least_greatest);
  if (greatest < node.least_greatest) node.least_greatest = greatest;
}

void VertexSubdivision::release(int n, std::vector<int>& held) {
  Node& leaf = nodes_[static_cast<std::size_t>(n)];
  held.insert(held.end(), leaf.vertices.begin(), leaf.vertices.end());
  leaf.vertices.clear();
  unresolved_leaves_ -= leaf.unresolved;
  leaf.unresolved = false;
}

void VertexSubdivision::update(int n, int v) {
  const Box b = nodes_[static_cast<std::size_t>(n)].box;
  const Bounds range = squared_distance_bounds(sites_[static_cast<std::size_t>(v)], b);
  if (range.lo > nodes_[static_cast<std::size_t>(n)].least_greatest) return;  // v is nowhere nearest in b: nothing below changes
  if (range.hi < nodes_[static_cast<std::size_t>(n)].least_greatest) nodes_[static_cast<std::size_t>(n)].least_greatest = range.hi;
  if (const int first = nodes_[static_cast<std::size_t>(n)].child; first >= 0) {
    for (int i = 0; i < 2; ++i) update(first + i, v);
    bound_by_children(n);
    return;
  }
  double U;
  std::vector<int> c = candidates_in(b, nodes_[static_cast<std::size_t>(n)].candidates, v, U);
  // v left out and every old candidate kept: the leaf's sites, and so its vertices, are as they were.
  if (c.size() == nodes_[static_cast<std::size_t>(n)].candidates.size() && std::find(c.begin(), c.end(), v) == c.end()) return;
  // Found again before the old ones are let go, so that a vertex that stays keeps its id.
  std::vector<int> held;
  release(n, held);
  nodes_[static_cast<std::size_t>(n)].candidates = std::move(c);
  settle(n);
  for (int id : held) {
    Vertex& q = vertices_[static_cast<std::size_t>(id)];
    if (--q.holders > 0) continue;
    released_.push_back(id);
    std::vector<int>& same_trio = by_trio_[q.sites];
    std::erase(same_trio, id);
    if (same_trio.empty()) by_trio_.erase(q.sites);
  }
}

void VertexSubdivision::insert(const MetricSite& s) {
  created_.clear();
  released_.clear();
  sites_.push_back(s);
  insertion_start_ = nodes_.size();
  update(0, static_cast<int>(sites_.size()) - 1);
  // In an order of their own (no two vertices share a trio and a place), not the order the tree
  // found them in, which depends on how its boxes are split.
  const auto key = [this](int id) {
    const Vertex& v = vertices_[static_cast<std::size_t>(id)];
    const Point2<double> p = v.box.approx();
    return std::tuple(v.sites, p.x, p.y);
  };
  std::sort(created_.begin(), created_.end(), [&](int a, int b) { return key(a) < key(b); });
}

std::vector<int> VertexSubdivision::candidates_near(const Box& b) const {
  std::vector<int> out;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (node.box.x1 < b.x0 || node.box.x0 > b.x1 || node.box.y1 < b.y0 || node.box.y0 > b.y1) continue;
    if (node.child >= 0) {
      for (int i = 0; i < 2; ++i) stack.push_back(node.child + i);
      continue;
    }
    out.insert(out.end(), node.candidates.begin(), node.candidates.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<VertexSubdivision::Leaf> VertexSubdivision::unresolved() const {
  std::vector<Leaf> out;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (node.unresolved) out.push_back({node.box, node.candidates});
    if (node.child >= 0)
      for (int i = 0; i < 2; ++i) stack.push_back(node.child + i);
  }
  return out;
}

}  // namespace anisocert::refiners::common

