// The faces of D|Ω (LS Definition 1: 2-faces, orphans, disconnected cells, islands) from the
// planar graph of nodes, arcs and boundary pieces. At a node, the edges leaving to the right are
// ordered by their heights on a vertical line just right of the node (closer than any other
// point of those edges, so no two of them meet in between), those leaving to the left likewise;
// that is the counter-clockwise order, exactly, without angles or curvatures. Walking each
// half-edge's next edge clockwise after its arrival traces the boundary cycles, each with one
// face on its left. A cycle is an outer boundary when at its lowest-leftmost point it turns
// downward (counter-clockwise); a hole belongs to the innermost outer cycle of the same site that
// contains it, decided by exact vertical ray casting.
#include "oracle/diagram/build.hpp"

#include <algorithm>
#include <stdexcept>

namespace anisocert::oracle::build {

namespace {

// The site on the left of a half-edge, from the first piece it runs along.
int left_site(const Diagram& d, const HalfEdge& h) {
  if (h.boundary >= 0) return d.boundary[h.boundary].site;
  const Arc& a = d.arcs[h.arc];
  const std::size_t p = h.reversed ? a.pieces.size() - 1 : 0;
  const bool increasing = a.forward[p] != h.reversed;
  const bool positive_above = a.pieces[p].branch.positive_side() > 0;  // F_vw > 0: w is closer
  const int above = positive_above ? a.w : a.v, below = positive_above ? a.v : a.w;
  return increasing ? above : below;
}

Branch boundary_branch(const Diagram& d, int edge) {
  const auto& dom = d.sheared.domain;
  return {line_conic(dom[edge], dom[(edge + 1) % dom.size()]), 0};
}

}  // namespace

std::vector<Span> spans_of(const Diagram& d, const HalfEdge& h) {
  std::vector<Span> out;
  if (h.boundary >= 0) {
    const BoundaryPiece& b = d.boundary[h.boundary];
    const LocatedPoint* p = &d.nodes[b.from].at;
    const LocatedPoint* q = &d.nodes[b.to].at;
    if (compare_x(*q, *p) == Sign::negative) std::swap(p, q);
    out.push_back({boundary_branch(d, b.edge), p, q});
    return out;
  }
  for (const Piece& p : d.arcs[h.arc].pieces) out.push_back({p.branch, &*p.left_point, &*p.right_point});
  return out;
}

bool cycle_contains(const Diagram& d, int c, const LocatedPoint& p) {
  int crossings = 0;
  for (int h : d.cycles[c].half_edges)
    for (const Span& s : spans_of(d, d.half_edges[h]))
      if (compare_x(p, *s.left) != Sign::negative && compare_x(p, *s.right) == Sign::negative &&
          s.branch.compare_point(p) == Sign::negative)
        ++crossings;
  return crossings % 2 == 1;
}

void Builder::build_half_edges() {
  germs_.assign(d_.nodes.size(), {});
  for (int a = 0; a < static_cast<int>(d_.arcs.size()); ++a) {
    const Arc& arc = d_.arcs[a];
    const int fwd = static_cast<int>(d_.half_edges.size());
    d_.half_edges.push_back({a, -1, false, arc.ends[0], arc.ends[1]});
    d_.half_edges.push_back({a, -1, true, arc.ends[1], arc.ends[0]});
    if (arc.closed) continue;
    const Piece& first = arc.pieces.front();
    germs_[arc.ends[0]].push_back(
        {fwd, fwd + 1, first.branch, arc.forward.front(), arc.forward.front() ? *first.right_point : *first.left_point});
    const Piece& last = arc.pieces.back();
    germs_[arc.ends[1]].push_back(
        {fwd + 1, fwd, last.branch, !arc.forward.back(), arc.forward.back() ? *last.left_point : *last.right_point});
  }
  for (int b = 0; b < static_cast<int>(d_.boundary.size()); ++b) {
    const BoundaryPiece& piece = d_.boundary[b];
    const int h = static_cast<int>(d_.half_edges.size());
    d_.half_edges.push_back({-1, b, false, piece.from, piece.to});
    const Branch branch = boundary_branch(d_, piece.edge);
    const LocatedPoint& p = d_.nodes[piece.from].at;
    const LocatedPoint& q = d_.nodes[piece.to].at;
    const bool right = compare_x(p, q) == Sign::negative;
    germs_[piece.from].push_back({h, -1, branch, right, q});
    germs_[piece.to].push_back({-1, h, branch, !right, p});
  }
  for (int n = 0; n < static_cast<int>(d_.nodes.size()); ++n) sort_germs(n);
}

void Builder::sort_germs(int node) {
  std::vector<Germ> right, left;
  for (Germ& g : germs_[node]) (g.right ? right : left).push_back(std::move(g));
  const LocatedPoint& at = d_.nodes[node].at;
  auto by_height = [&](std::vector<Germ>& gs, bool to_right) {
    if (gs.size() < 2) return;
    const LocatedPoint* nearest_far = &gs[0].far;
    for (const Germ& g : gs)
      if (compare_x(g.far, *nearest_far) == (to_right ? Sign::negative : Sign::positive)) nearest_far = &g.far;
    const Rational x = to_right ? rational_between(at, *nearest_far) : rational_between(*nearest_far, at);
    std::vector<std::pair<LocatedPoint, Germ>> keyed;
    for (Germ& g : gs) keyed.emplace_back(g.branch.at(x, width_), std::move(g));
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
      return compare_y(a.first, b.first) == Sign::negative;
    });
    gs.clear();
    for (auto& [p, g] : keyed) gs.push_back(std::move(g));
  };
  by_height(right, true);
  by_height(left, false);
  std::reverse(left.begin(), left.end());
  germs_[node] = std::move(right);
  for (Germ& g : left) germs_[node].push_back(std::move(g));
}

void Builder::build_cycles() {
  // next(h): at h's target, the edge clockwise after the one h arrives by.
  auto next = [&](int h) {
    const HalfEdge& e = d_.half_edges[h];
    if (e.target < 0) return h;  // a closed arc
    const auto& gs = germs_[e.target];
    for (std::size_t i = 0; i < gs.size(); ++i)
      if (gs[i].incoming == h) {
        const int out = gs[(i + gs.size() - 1) % gs.size()].outgoing;
        if (out < 0) throw std::logic_error("oracle: a boundary walk leaves the domain");
        return out;
      }
    throw std::logic_error("oracle: a half-edge is missing from its target's edges");
  };
  for (int h0 = 0; h0 < static_cast<int>(d_.half_edges.size()); ++h0) {
    if (d_.half_edges[h0].cycle >= 0) continue;
    Cycle c;
    c.site = left_site(d_, d_.half_edges[h0]);
    const int id = static_cast<int>(d_.cycles.size());
    for (int h = h0; d_.half_edges[h].cycle < 0; h = next(h)) {
      d_.half_edges[h].cycle = id;
      c.half_edges.push_back(h);
      if (left_site(d_, d_.half_edges[h]) != c.site)
        throw std::logic_error("oracle: a face boundary has two different sites on its left");
    }
    d_.cycles.push_back(std::move(c));
  }
  // Orientation at the lowest-leftmost point of each cycle.
  for (Cycle& c : d_.cycles) {
    struct Visit {
      const LocatedPoint* at;
      int node;                 // ≥ 0: arrival by `in`, departure by `out`
      int in, out;
      int side_in, side_out;    // at a joint: the branches before and after
    };
    std::vector<Visit> visits;
    for (std::size_t i = 0; i < c.half_edges.size(); ++i) {
      const HalfEdge& h = d_.half_edges[c.half_edges[i]];
      if (h.arc >= 0) {
        const Arc& a = d_.arcs[h.arc];
        const int n = static_cast<int>(a.pieces.size());
        for (int k = 0; k + 1 < n; ++k) {  // joints inside the arc, in walking order
          const int p = h.reversed ? n - 1 - k : k, q = h.reversed ? p - 1 : p + 1;
          const bool inc = a.forward[p] != h.reversed;
          visits.push_back({inc ? &*a.pieces[p].right_point : &*a.pieces[p].left_point, -1, -1, -1,
                            a.pieces[p].branch.side, a.pieces[q].branch.side});
        }
        if (a.closed) {  // the joint closing the loop
          const int p = h.reversed ? 0 : n - 1, q = h.reversed ? n - 1 : 0;
          const bool inc = a.forward[p] != h.reversed;
          visits.push_back({inc ? &*a.pieces[p].right_point : &*a.pieces[p].left_point, -1, -1, -1,
                            a.pieces[p].branch.side, a.pieces[q].branch.side});
          continue;
        }
      }
      visits.push_back({&d_.nodes[h.target].at, h.target, c.half_edges[i],
                        c.half_edges[(i + 1) % c.half_edges.size()], 0, 0});
    }
    const Visit* low = &visits[0];
    for (const Visit& v : visits) {
      const Sign sx = compare_x(*v.at, *low->at);
      if (sx == Sign::negative || (sx == Sign::zero && compare_y(*v.at, *low->at) == Sign::negative)) low = &v;
    }
    if (low->node < 0) {
      c.outer = low->side_in > 0 && low->side_out < 0;
      continue;
    }
    c.outer = true;
    const auto& gs = germs_[low->node];
    for (const Visit& v : visits) {
      if (v.node != low->node) continue;
      int in = -1, out = -1;
      for (int g = 0; g < static_cast<int>(gs.size()); ++g) {
        if (gs[g].incoming == v.in) in = g;
        if (gs[g].outgoing == v.out) out = g;
      }
      if (!gs[in].right || !gs[out].right) throw std::logic_error("oracle: an edge leaves a cycle's leftmost point leftward");
      if (out > in) c.outer = false;
    }
  }
}

void Builder::build_faces() {
  std::vector<int> face_of_cycle(d_.cycles.size(), -1);
  std::vector<std::vector<int>> faces_of_site(d_.sheared.sites.size());
  for (int c = 0; c < static_cast<int>(d_.cycles.size()); ++c)
    if (d_.cycles[c].outer) {
      face_of_cycle[c] = static_cast<int>(d_.faces.size());
      faces_of_site[static_cast<std::size_t>(d_.cycles[c].site)].push_back(face_of_cycle[c]);
      d_.faces.push_back({d_.cycles[c].site, c, {}, false});
    }
  // A point on a cycle, off every other cycle of the same site.
  auto point_on = [&](int c) {
    const HalfEdge& h = d_.half_edges[d_.cycles[c].half_edges[0]];
    if (h.arc >= 0) {
      const Piece& p = d_.arcs[h.arc].pieces[0];
      return p.branch.at(p.sample_x, width_);
    }
    const Span s = spans_of(d_, h)[0];
    return s.branch.at(rational_between(*s.left, *s.right), width_);
  };
  // The innermost of the outer cycles of `site` containing p.
  auto innermost = [&](int site, const LocatedPoint& p, int skip) {
    std::vector<int> around;
    for (int f : faces_of_site[static_cast<std::size_t>(site)]) {
      const int c = d_.faces[static_cast<std::size_t>(f)].outer_cycle;
      if (c != skip && cycle_contains(d_, c, p)) around.push_back(c);
    }
    for (int c : around) {
      const LocatedPoint q = point_on(c);
      bool inside_all = true;
      for (int o : around)
        if (o != c && !cycle_contains(d_, o, q)) inside_all = false;
      if (inside_all) return c;
    }
    return -1;
  };
  for (int c = 0; c < static_cast<int>(d_.cycles.size()); ++c) {
    if (d_.cycles[c].outer) continue;
    const int o = innermost(d_.cycles[c].site, point_on(c), c);
    if (o < 0) throw std::logic_error("oracle: a hole is inside no face of its site");
    d_.faces[face_of_cycle[o]].holes.push_back(c);
  }
  // The face holding site s: it is the only nearest site at s, so when s is on ∂Ω it lies on (an
  // end of, or inside) a boundary piece of its own cell, on that piece's cycle; otherwise it is
  // strictly inside the innermost outer cycle of its site around it.
  std::vector<std::vector<int>> boundary_half_edges_of_site(d_.sheared.sites.size());
  for (int h = 0; h < static_cast<int>(d_.half_edges.size()); ++h)
    if (const HalfEdge& e = d_.half_edges[h]; e.boundary >= 0)
      boundary_half_edges_of_site[static_cast<std::size_t>(d_.boundary[e.boundary].site)].push_back(h);
  auto home_of = [&](int s, const LocatedPoint& site) {
    if (domain_position(site).edges.empty()) return innermost(s, site, -1);
    for (int h : boundary_half_edges_of_site[static_cast<std::size_t>(s)]) {
      const HalfEdge& e = d_.half_edges[h];
      const Span span = spans_of(d_, e)[0];
      if (compare_x(site, *span.left) != Sign::negative && compare_x(site, *span.right) != Sign::positive &&
          span.branch.compare_point(site) == Sign::zero)
        return e.cycle;
    }
    throw std::logic_error("oracle: a site on ∂Ω is on no boundary piece of its cell");
  };
  for (int s = 0; s < static_cast<int>(d_.sheared.sites.size()); ++s) {
    const LocatedPoint site = LocatedPoint::rational(d_.sheared.sites[s].x, d_.sheared.sites[s].y);
    const int home = home_of(s, site);
    for (int f : faces_of_site[static_cast<std::size_t>(s)])
      d_.faces[static_cast<std::size_t>(f)].orphan = d_.faces[static_cast<std::size_t>(f)].outer_cycle != home;
  }
}

}  // namespace anisocert::oracle::build

namespace anisocert::oracle {

Location locate(const Diagram& d, const Point2<Rational>& point) {
  const LocatedPoint p = LocatedPoint::rational(point.x + d.shear * point.y, point.y);
  for (int n = 0; n < static_cast<int>(d.nodes.size()); ++n)
    if (same_point(d.nodes[n].at, p)) return {Location::Kind::node, n, d.nodes[n].sites};
  // An arc's pieces meet at its joints (vertical tangents, not nodes): a point there is the end of
  // two pieces and strictly inside neither.
  for (int a = 0; a < static_cast<int>(d.arcs.size()); ++a)
    for (const Piece& piece : d.arcs[a].pieces)
      if ((piece.left < 0 && same_point(p, *piece.left_point)) || (piece.right < 0 && same_point(p, *piece.right_point)) ||
          (compare_x(p, *piece.left_point) == Sign::positive && compare_x(p, *piece.right_point) == Sign::negative &&
           piece.branch.compare_point(p) == Sign::zero))
        return {Location::Kind::arc, a, {d.arcs[a].v, d.arcs[a].w}};
  for (int b = 0; b < static_cast<int>(d.boundary.size()); ++b) {
    HalfEdge h{-1, b};
    const build::Span s = build::spans_of(d, h)[0];
    if (compare_x(p, *s.left) == Sign::positive && compare_x(p, *s.right) == Sign::negative &&
        s.branch.compare_point(p) == Sign::zero)
      return {Location::Kind::boundary, b, {d.boundary[b].site}};
  }
  for (int f = 0; f < static_cast<int>(d.faces.size()); ++f) {
    const Face& face = d.faces[f];
    if (!build::cycle_contains(d, face.outer_cycle, p)) continue;
    bool in_hole = false;
    for (int h : face.holes) in_hole = in_hole || build::cycle_contains(d, h, p);
    if (!in_hole) return {Location::Kind::face, f, {face.site}};
  }
  throw std::invalid_argument("locate: the point is outside the domain");
}

}  // namespace anisocert::oracle
