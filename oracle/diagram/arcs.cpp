// The arcs of D|Ω (LS §3: Voronoi arcs are pieces of bisector conics) and the pieces of ∂Ω.
// Each bisector F_vw of a candidate pair is cut at every point where the status "v and w are the
// nearest sites and the point is in Ω" can change: the Voronoi vertices owned by v and w (where a
// third site becomes equidistant), the crossings with ∂Ω, the singular point of a line-pair
// bisector, and the vertical tangents where the upper and lower branches meet. Between two
// consecutive cuts of a branch the status is constant, so one exact sample decides the piece.
// Kept pieces are chained through vertical tangents into arcs.
#include "oracle/algebraic/common_points.hpp"
#include "oracle/algebraic/shared_line.hpp"
#include "oracle/diagram/build.hpp"
#include "oracle/parallel_for.hpp"

#include <algorithm>
#include <stdexcept>

namespace anisocert::oracle::build {

namespace {

struct Cut {
  LocatedPoint at;
  int node = -1;        // a node of D|Ω (an id, or pending_ref(k) for a new one), or −1
  bool joint = false;   // a vertical tangent (on both branches)
  bool on_upper = true, on_lower = true;
};

bool boxes_meet(const BoxBounds& a, const BoxBounds& b) {
  return !(a.x_hi < b.x_lo || b.x_hi < a.x_lo || a.y_hi < b.y_lo || b.y_hi < a.y_lo);
}

}  // namespace

void Builder::build_arcs() {
  const std::size_t n = cand_.pairs.size();
  std::vector<PairArcs> found(n);
  parallel_for(
      n, threads_, [&](std::size_t i) { found[i] = arcs_of_pair(i); },
      [&](std::size_t done) {
        if (progress_) progress_("arcs: " + std::to_string(done) + " of " + std::to_string(n) + " candidate pairs");
      });
  for (PairArcs& f : found) add_arcs(f);
}

// Registers a pair's new nodes and adds its arcs, with their node references resolved.
void Builder::add_arcs(PairArcs& found) {
  std::vector<int> id;
  for (const PendingNode& p : found.pending) id.push_back(register_node(p.kind, p.at, p.owners));
  const auto resolve = [&](int& ref) {
    if (ref <= -2) ref = id[static_cast<std::size_t>(-2 - ref)];
  };
  for (Arc& arc : found.arcs) {
    resolve(arc.ends[0]), resolve(arc.ends[1]);
    for (Piece& p : arc.pieces) resolve(p.left), resolve(p.right);
    for (int e : {arc.ends[0], arc.ends[1]})  // LS Theorem 7: an arc cut by the restriction to Ω
      if (e >= 0 && d_.nodes[e].sites.size() == 2)
        for (int k : d_.nodes[e].boundary_edges)
          if (std::find(arc.cut_by_edges.begin(), arc.cut_by_edges.end(), k) == arc.cut_by_edges.end())
            arc.cut_by_edges.push_back(k);
    std::sort(arc.cut_by_edges.begin(), arc.cut_by_edges.end());
    d_.arcs.push_back(std::move(arc));
  }
}

PairArcs Builder::arcs_of_pair(std::size_t i) const {
  const int v = cand_.pairs[i].first, w = cand_.pairs[i].second;
  const BoxBounds& region = cand_.pair_region[i];
  const IntervalBox search = sheared_box(region);
  PairArcs out;
  const auto pending = [&](Node::Kind kind, const LocatedPoint& p, const std::vector<int>& owners) {
    out.pending.push_back({kind, p, owners});
    return pending_ref(out.pending.size() - 1);
  };
  const Conic F = bisector_conic(d_.sheared, v, w);
  const bool line = is_line(F);
  std::vector<Cut> cuts;
  auto add_cut = [&](const LocatedPoint& p, int node, bool joint) {
    Cut c{p, node, joint};
    if (!line && !joint) {
      Branch upper{F, 1};
      c.on_upper = upper.holds(p);
      c.on_lower = Branch{F, -1}.holds(p);
    }
    cuts.push_back(std::move(c));
  };
  // Voronoi vertices (and nodes found earlier) owned by v and w.
  if (auto it = nodes_of_pair_.find({v, w}); it != nodes_of_pair_.end())
    for (int n : it->second) add_cut(d_.nodes[n].at, n, false);
  // Crossings with ∂Ω (original-coordinate bounding boxes decide which edges can meet the arc).
  const auto& orig = d_.domain;
  const std::size_t m = orig.size();
  for (std::size_t k = 0; k < m; ++k) {
    const auto& a = orig[k];
    const auto& b = orig[(k + 1) % m];
    const auto ax = anisocert::FilterInterval::around(a.x), ay = anisocert::FilterInterval::around(a.y);
    const auto bx = anisocert::FilterInterval::around(b.x), by = anisocert::FilterInterval::around(b.y);
    const BoxBounds edge_box{std::min(ax.lo, bx.lo), std::max(ax.hi, bx.hi), std::min(ay.lo, by.lo), std::max(ay.hi, by.hi)};
    if (!boxes_meet(edge_box, region)) continue;
    const auto& sa = d_.sheared.domain[k];
    const auto& sb = d_.sheared.domain[(k + 1) % m];
    const Conic edge_line = line_conic(sa, sb);
    // The crossings that can be arc ends lie in the pair's region and on the edge.
    const IntervalBox edge = sheared_box(edge_box);
    const IntervalBox on_edge{{std::max(search.x.lo, edge.x.lo), std::min(search.x.hi, edge.x.hi)},
                              {std::max(search.y.lo, edge.y.lo), std::min(search.y.hi, edge.y.hi)}};
    CommonPoints x = common_points(F, edge_line, on_edge, width_);
    if (x.shared_component) {
      // F contains the edge's line: its pieces on the edge lie on ∂Ω, not inside Ω, and are
      // dropped by their samples; the edge's ends and the other component's crossing are cuts.
      decline_if_tied_on_edge(v, w, static_cast<int>(k));
      for (const auto* corner : {&sa, &sb}) add_cut(LocatedPoint::rational(corner->x, corner->y), -1, false);
      const Conic rest = line_quotient(F, edge_line);
      x = rest.d == 0 && rest.e == 0 ? CommonPoints{} : exact_common_points(rest, edge_line, width_);
      if (x.shared_component) x = CommonPoints{};  // F is the edge line twice: impossible for a bisector
    }
    for (const LocatedPoint& p : x.points) {
      if (compare_x(p, std::min(sa.x, sb.x)) == Sign::negative || compare_x(p, std::max(sa.x, sb.x)) == Sign::positive)
        continue;
      const Nearest n = nearest(p, v, {w});
      add_cut(p, n.closer ? -1 : pending(Node::Kind::domain_crossing, p, n.owners), false);
    }
  }
  // Vertical tangents and the singular point: the common points of F and ∂F/∂y.
  if (!line) {
    const CommonPoints x = common_points(F, derivative_in_y(F), search, width_);
    for (const LocatedPoint& p : x.points) {
      const Conic Fx{0, 0, 0, 2 * F.a, F.b, F.d};
      if (p.sign_of(Fx) == Sign::zero) {  // singular: the two lines of a line-pair bisector cross
        const Nearest n = nearest(p, v, {w});
        const bool kept = !n.closer && !domain_position(p).outside();
        add_cut(p, kept ? pending(Node::Kind::singular, p, n.owners) : -1, false);
        cuts.back().on_upper = cuts.back().on_lower = true;
      } else {
        add_cut(p, -1, true);
      }
    }
  }
  // Merge cuts at the same point (a joint that is also a node is a node).
  for (std::size_t i = 0; i < cuts.size(); ++i)
    for (std::size_t j = i + 1; j < cuts.size();) {
      if (same_point(cuts[i].at, cuts[j].at)) {
        // Two references to one point name one node: an existing one is preferred to a pending
        // one, which would resolve to it.
        if (cuts[j].node != -1 && (cuts[i].node == -1 || (cuts[i].node <= -2 && cuts[j].node >= 0))) cuts[i].node = cuts[j].node;
        cuts[i].joint = cuts[i].joint || cuts[j].joint;
        cuts[i].on_upper = cuts[i].on_upper || cuts[j].on_upper || cuts[j].joint;
        cuts[i].on_lower = cuts[i].on_lower || cuts[j].on_lower || cuts[j].joint;
        cuts.erase(cuts.begin() + static_cast<long>(j));
      } else {
        ++j;
      }
    }
  for (Cut& c : cuts)
    if (c.node != -1) c.joint = false;

  // Pieces, branch by branch: between consecutive cuts, where the branch exists.
  struct Kept {
    Piece piece;
    int left_cut, right_cut;
  };
  std::vector<Kept> kept;
  const Polynomial disc = discriminant_in_x(F);
  for (int side : line ? std::vector<int>{0} : std::vector<int>{1, -1}) {
    std::vector<int> on;
    for (int i = 0; i < static_cast<int>(cuts.size()); ++i)
      if (side == 0 || (side > 0 ? cuts[i].on_upper : cuts[i].on_lower)) on.push_back(i);
    std::sort(on.begin(), on.end(), [&](int a, int b) { return compare_x(cuts[a].at, cuts[b].at) == Sign::negative; });
    const Branch branch{F, side};
    for (std::size_t k = 0; k + 1 < on.size(); ++k) {
      const Cut& a = cuts[on[k]];
      const Cut& b = cuts[on[k + 1]];
      const Rational xm = rational_between(a.at, b.at);
      if (side != 0 && disc.sign_at(xm) != Sign::positive) continue;  // no branch between a and b
      const LocatedPoint s = branch.at(xm, width_);
      const DomainPosition pos = domain_position(s);
      if (!pos.inside) continue;
      const Nearest n = nearest(s, v, {w});
      if (n.closer) continue;
      if (n.owners.size() != 2) throw std::logic_error("oracle: a third site is equidistant inside an arc piece");
      kept.push_back({Piece{branch, a.node, b.node, a.at, b.at, xm}, on[k], on[k + 1]});
    }
  }
  if (kept.empty()) return out;

  // Chain pieces through joints into arcs.
  std::vector<std::vector<int>> at_cut(cuts.size());
  for (int i = 0; i < static_cast<int>(kept.size()); ++i) {
    at_cut[kept[i].left_cut].push_back(i);
    at_cut[kept[i].right_cut].push_back(i);
  }
  for (std::size_t c = 0; c < cuts.size(); ++c)
    if (cuts[c].node == -1 && !at_cut[c].empty() && at_cut[c].size() != 2)
      throw std::logic_error("oracle: an arc of sites " + std::to_string(v) + ", " + std::to_string(w) +
                             " ends at a point that is not a node");
  std::vector<bool> used(kept.size(), false);
  auto trace = [&](int first, int from_cut) {
    Arc arc{v, w, F, {}, {}, {-1, -1}, false, {}, true, std::nullopt, Conic{}};
    arc.ends[0] = cuts[from_cut].node;
    int piece = first, cut = from_cut;
    while (true) {
      used[piece] = true;
      const bool forward = kept[piece].left_cut == cut;
      arc.pieces.push_back(kept[piece].piece);
      arc.forward.push_back(forward);
      cut = forward ? kept[piece].right_cut : kept[piece].left_cut;
      if (cuts[cut].node != -1) {
        arc.ends[1] = cuts[cut].node;
        break;
      }
      const auto& next = at_cut[cut];
      const int other = next[0] == piece ? next[1] : next[0];
      if (used[other]) {  // back at the start: a closed arc
        arc.closed = true;
        break;
      }
      piece = other;
    }
    check_arc_wedges(arc, search);
    out.arcs.push_back(std::move(arc));
  };
  for (int c = 0; c < static_cast<int>(cuts.size()); ++c)
    if (cuts[c].node != -1)
      for (int p : at_cut[c])
        if (!used[p]) trace(p, c);
  for (int p = 0; p < static_cast<int>(kept.size()); ++p)
    if (!used[p]) trace(p, kept[p].left_cut);
  return out;
}

// LS Definition 3 for an arc: every point in the open wedge(v, w). The arc is connected, so it
// leaves the wedge only by meeting one of the two wedge lines; a line meeting a piece inside its
// x-range is a violation, and otherwise one sample decides the piece. The arc lies in its pair's
// region, so the meeting points inside its pieces do too.
void Builder::check_arc_wedges(Arc& arc, const IntervalBox& region) const {
  for (const auto& [from, to] : {std::pair{arc.v, arc.w}, std::pair{arc.w, arc.v}}) {
    const Conic line = wedge_form(d_.sheared, from, to);
    const CommonPoints x = common_points(arc.bisector, line, region, width_);
    for (const Piece& p : arc.pieces) {
      if (!x.shared_component)
        for (const LocatedPoint& q : x.points) {
          if (!p.branch.holds(q) || compare_x(q, *p.left_point) != Sign::positive ||
              compare_x(q, *p.right_point) != Sign::negative)
            continue;
          arc.wedged = false, arc.witness = q, arc.witness_line = line;
          return;
        }
      const LocatedPoint s = p.branch.at(p.sample_x, width_);
      if (s.sign_of(line) != Sign::positive) {
        arc.wedged = false, arc.witness = s, arc.witness_line = Conic{0, 0, 0, 1, 0, -p.sample_x};
        return;
      }
    }
  }
}

// LS Definition 3 for a node: in wedge(a, b) for every pair of its owners.
void Builder::check_node_wedges() {
  for (Node& n : d_.nodes)
    for (std::size_t i = 0; i < n.sites.size() && n.wedged; ++i)
      for (std::size_t j = i + 1; j < n.sites.size() && n.wedged; ++j) {
        const int a = n.sites[i], b = n.sites[j];
        if (n.at.sign_of(wedge_form(d_.sheared, a, b)) != Sign::positive ||
            n.at.sign_of(wedge_form(d_.sheared, b, a)) != Sign::positive)
          n.wedged = false, n.unwedged_pair = {a, b};
      }
}

int Builder::owner_of_edge_point(int edge, const LocatedPoint& a, const LocatedPoint& b) const {
  // The nearest site at rational points strictly between a and b on the edge; the boundary piece
  // holds no node, so at most finitely many of its points (tangencies from outside) have a tie.
  const auto& sa = d_.sheared.domain[edge];
  const auto& sb = d_.sheared.domain[(edge + 1) % d_.sheared.domain.size()];
  const bool increasing = compare_x(a, b) == Sign::negative;
  const LocatedPoint& left = increasing ? a : b;
  Rational x = rational_between(left, increasing ? b : a);
  for (int attempt = 0; attempt < 64; ++attempt, x = rational_between(left, x)) {  // towards the left end
    const Rational y = sa.y + (sb.y - sa.y) * (x - sa.x) / (sb.x - sa.x);
    const LocatedPoint p = LocatedPoint::rational(x, y);
    const Nearest n = nearest_rational(p);
    if (n.owners.size() == 1) return n.owners[0];
  }
  throw std::logic_error("oracle: no point with a unique nearest site on a boundary piece of edge " + std::to_string(edge));
}

void Builder::build_boundary() {
  const std::size_t m = d_.sheared.domain.size();
  for (std::size_t k = 0; k < m; ++k) {
    std::vector<int> on;
    for (int i = 0; i < static_cast<int>(d_.nodes.size()); ++i)
      if (std::find(d_.nodes[i].boundary_edges.begin(), d_.nodes[i].boundary_edges.end(), static_cast<int>(k)) !=
          d_.nodes[i].boundary_edges.end())
        on.push_back(i);
    const bool increasing = d_.sheared.domain[k].x < d_.sheared.domain[(k + 1) % m].x;
    std::sort(on.begin(), on.end(), [&](int a, int b) {
      return compare_x(d_.nodes[a].at, d_.nodes[b].at) == (increasing ? Sign::negative : Sign::positive);
    });
    for (std::size_t i = 0; i + 1 < on.size(); ++i)
      d_.boundary.push_back({static_cast<int>(k), on[i], on[i + 1],
                             owner_of_edge_point(static_cast<int>(k), d_.nodes[on[i]].at, d_.nodes[on[i + 1]].at)});
  }
}

}  // namespace anisocert::oracle::build
