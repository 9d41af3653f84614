// The nodes of D|Ω: the corners of Ω and the Voronoi vertices (LS Definition 1: points of Ω
// equidistant from three or more sites with no site closer), found exactly as common points of
// two bisector conics (LS Proposition 2) for every candidate triple of the certified
// subdivision (candidate_subdivision.hpp: the triples include every vertex's owners).
#include "oracle/algebraic/common_points.hpp"
#include "oracle/algebraic/shared_line.hpp"
#include "oracle/diagram/build.hpp"
#include "oracle/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace anisocert::oracle::build {


DomainEdges::DomainEdges(const Mesh<Rational>& sh) {
  const std::size_t m = sh.domain.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Point2<Rational>& a = sh.domain[k];
    const Point2<Rational>& b = sh.domain[(k + 1) % m];
    const Conic line = line_conic(a, b);
    const Rational xl = std::min(a.x, b.x), xr = std::max(a.x, b.x);
    edges_.push_back({xl, xr, FilterInterval::around(xl), FilterInterval::around(xr), line, IntervalConic::around(line), a});
  }
}

DomainPosition DomainEdges::position(const LocatedPoint& p) const {
  DomainPosition pos;
  int crossings = 0;
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const Edge& e = edges_[k];
    if (p.x.hi < e.xl_box.lo || e.xr_box.hi < p.x.lo) continue;  // outside the edge's x-range
    const Sign lo = compare_x(p, e.xl), hi = compare_x(p, e.xr);
    if (lo == Sign::negative || hi == Sign::positive) continue;
    // The side of the line (non-vertical: G = e·(y − y_line)): the box first, then exactly.
    const IntervalConic& g = e.line_box;
    const FilterInterval value = g.d * p.x + g.e * p.y + g.f;
    Sign side;
    if (const auto s = value.sign(); s && *s != Sign::zero && (g.e.lo > 0 || g.e.hi < 0))
      side = (*s == Sign::positive) == (g.e.lo > 0) ? Sign::positive : Sign::negative;
    else
      side = Branch{e.line, 0}.compare_point(p);
    if (side == Sign::zero) {
      pos.edges.push_back(static_cast<int>(k));
      continue;
    }
    if (lo != Sign::negative && hi == Sign::negative && side == Sign::negative) ++crossings;  // [xl, xr), above p
  }
  for (int k : pos.edges) {  // a corner lies on two edges
    const Point2<Rational>& a = edges_[static_cast<std::size_t>(k)].a;
    if (same_point(p, LocatedPoint::rational(a.x, a.y))) pos.corner = k;
  }
  pos.inside = pos.edges.empty() && crossings % 2 == 1;
  return pos;
}

Nearest Builder::nearest(const LocatedPoint& p, int v, const std::vector<int>& equal) const {
  auto value = [&](int u) { return distance_at(u, p); };
  // Every nearest site of p is a candidate of the leaf holding p (candidate_subdivision.hpp).
  const std::vector<int> near = sites_near(p);
  if (!std::binary_search(near.begin(), near.end(), v)) return {true, {}};  // a site is strictly closer than v
  const FilterInterval qv = value(v);
  Nearest out;
  out.owners.push_back(v);
  for (int u : near) {
    if (u == v) continue;
    if (std::find(equal.begin(), equal.end(), u) != equal.end()) {
      out.owners.push_back(u);
      continue;
    }
    const FilterInterval qu = value(u);
    if (qu.lo > qv.hi) continue;  // u is strictly farther
    Sign s = Sign::zero;          // sign(Q_u − Q_v) at p
    if (qu.hi < qv.lo)
      s = Sign::negative;
    else
      s = p.sign_of(bisector_conic(d_.sheared, u, v));
    if (s == Sign::negative) return {true, {}};
    if (s == Sign::zero) out.owners.push_back(u);
  }
  std::sort(out.owners.begin(), out.owners.end());
  return out;
}

int Builder::register_node(Node::Kind kind, const LocatedPoint& p, const std::vector<int>& owners) {
  // The nodes whose x-boxes meet p's: their lower ends lie in [p.x.lo − node_width_, p.x.hi].
  std::vector<int> near = wide_nodes_;
  for (auto it = node_index_.lower_bound(FilterInterval::next_down(p.x.lo - node_width_)); it != node_index_.end() && it->first <= p.x.hi; ++it)
    near.push_back(it->second);
  std::sort(near.begin(), near.end());
  for (int i : near) {
    Node& n = d_.nodes[static_cast<std::size_t>(i)];
    if (!same_point(n.at, p)) continue;
    if (static_cast<int>(kind) < static_cast<int>(n.kind)) n.kind = kind;  // voronoi < … < corner
    return i;
  }
  const DomainPosition pos = domain_position(p);
  Node n{kind, p, owners, pos.edges, pos.corner};
  d_.nodes.push_back(std::move(n));
  const int id = static_cast<int>(d_.nodes.size()) - 1;
  const double w = p.x.hi - p.x.lo;
  if (std::isfinite(w)) {
    node_index_.emplace(p.x.lo, id);
    node_width_ = std::max(node_width_, w);
  } else {
    wide_nodes_.push_back(id);
  }
  for (std::size_t i = 0; i < owners.size(); ++i)
    for (std::size_t j = i + 1; j < owners.size(); ++j) nodes_of_pair_[{owners[i], owners[j]}].push_back(id);
  return id;
}

void Builder::add_corners() {
  for (const Point2<Rational>& c : d_.sheared.domain) {
    const LocatedPoint p = LocatedPoint::rational(c.x, c.y);
    register_node(Node::Kind::corner, p, nearest_rational(p).owners);  // its nearest sites
  }
}

// The points of the triple's leaves equidistant from its three sites with none closer. The
// filtered search is confined to the triple's region (every Voronoi vertex of the triple lies in
// one of its leaves); the exact path takes every common point and drops those where a site is
// closer, which the region's points outside every leaf of the triple all have.
std::vector<VertexCandidate> Builder::vertices_of_triple(std::size_t i, std::size_t& candidate_points) const {
  const auto& t = cand_.triples[i];
  std::vector<VertexCandidate> out;
  CommonPoints x = common_points(bisectors(t[0], t[1], t[2]), sheared_box(cand_.triple_region[i]), width_);
  if (x.shared_component) {
    const Conic A = bisector_conic(d_.sheared, t[0], t[1]), B = bisector_conic(d_.sheared, t[0], t[2]);
    // A = G·H1, B = G·H2: the three sites tie along the line G (declined only if that tie is
    // part of D|Ω); the isolated common points are those of H1 and H2.
    const std::optional<Conic> G = common_line(A, B);
    if (!G)
      throw std::domain_error("sites " + std::to_string(t[0]) + ", " + std::to_string(t[1]) + " and " +
                              std::to_string(t[2]) + " are equidistant along a whole conic; such inputs are not supported yet");
    decline_if_tied_on_line(t[0], t[1], t[2], *G);
    const Conic H1 = line_quotient(A, *G), H2 = line_quotient(B, *G);
    if (H1.d == 0 && H1.e == 0) return out;  // A is the line G itself: its points are all on G
    if (H2.d == 0 && H2.e == 0) return out;
    x = exact_common_points(H1, H2, width_);
    if (x.shared_component) return out;  // H1 = H2: only the two lines, ties checked on G; H1 separately
  }
  for (LocatedPoint& p : x.points) {
    ++candidate_points;
    Nearest n = nearest(p, t[0], {t[1], t[2]});
    if (n.closer) continue;
    if (domain_position(p).outside()) continue;
    out.push_back({std::move(p), std::move(n.owners)});
  }
  return out;
}

void Builder::find_vertices() {
  const std::size_t n = cand_.triples.size();
  std::vector<std::vector<VertexCandidate>> found(n);
  std::vector<std::size_t> points(n, 0);
  parallel_for(
      n, threads_, [&](std::size_t i) { found[i] = vertices_of_triple(i, points[i]); },
      [&](std::size_t done) {
        if (progress_) progress_("vertices: " + std::to_string(done) + " of " + std::to_string(n) + " candidate triples");
      });
  for (std::size_t i = 0; i < n; ++i) {
    d_.stats.candidate_points += points[i];
    for (const VertexCandidate& v : found[i]) register_node(Node::Kind::voronoi, v.at, v.owners);
  }
}

}  // namespace anisocert::oracle::build
