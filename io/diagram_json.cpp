#include "io/diagram_json.hpp"

#include "oracle/algebraic/conic_intersection.hpp"

namespace anisocert::io {

using oracle::AlgebraicPoint;
using oracle::Conic;
using oracle::Diagram;

namespace {

OrderedJson conic_json(const Conic& c) {
  return OrderedJson::array({to_exact_string(c.a), to_exact_string(c.b), to_exact_string(c.c), to_exact_string(c.d),
                             to_exact_string(c.e), to_exact_string(c.f)});
}

const char* kind_name(oracle::Node::Kind k) {
  switch (k) {
    case oracle::Node::Kind::voronoi: return "voronoi";
    case oracle::Node::Kind::domain_crossing: return "domain_crossing";
    case oracle::Node::Kind::singular: return "singular";
    case oracle::Node::Kind::corner: return "corner";
  }
  return "";
}

bool boxes_overlap(const oracle::RealAlgebraic& ax, const oracle::RealAlgebraic& ay, const oracle::RealAlgebraic& bx,
                   const oracle::RealAlgebraic& by) {
  return !(ax.hi() < bx.lo() || bx.hi() < ax.lo() || ay.hi() < by.lo() || by.hi() < ay.lo());
}

// Two curves through a node with two or more owners: two bisectors of its owners, or a bisector
// and the edge of Ω it is on, or (the singular point of a line pair) the bisector and its ∂/∂y.
std::pair<Conic, Conic> node_curves(const Diagram& d, const oracle::Node& n) {
  const Conic F = oracle::bisector_conic(d.sheared, n.sites[0], n.sites[1]);
  if (n.sites.size() >= 3) return {F, oracle::bisector_conic(d.sheared, n.sites[0], n.sites[2])};
  if (!n.boundary_edges.empty()) {
    const auto& dom = d.sheared.domain;
    const int k = n.boundary_edges[0];
    return {F, oracle::line_conic(dom[k], dom[(k + 1) % dom.size()])};
  }
  return {F, oracle::derivative_in_y(F)};
}

}  // namespace

OrderedJson point_certificate(const Diagram& d, const oracle::LocatedPoint& p, const Conic& A, const Conic& B) {
  const auto [ax, ay] = d.original_xy(p);
  const auto& x = p.exact().x();
  const auto& y = p.exact().y();
  const auto rx = x.as_rational(), ry = y.as_rational();
  if (rx && ry) return {{"exact", true}, {"x", to_exact_string(*rx - d.shear * *ry)}, {"y", to_exact_string(*ry)}};
  // The same point among the common points of the curves in the input's coordinates: the shear
  // keeps y and, at equal y, the order of x.
  const Conic A0 = oracle::shear_conic(A, d.shear), B0 = oracle::shear_conic(B, d.shear);
  const auto sheared = oracle::intersect(A, B).points;
  auto original = oracle::intersect(A0, B0).points;
  int rank = 0;
  for (const auto& q : sheared)
    if (compare(q.point.y(), y) == Sign::zero && compare(q.point.x(), x) == Sign::negative) ++rank;
  const AlgebraicPoint* match = nullptr;
  for (const auto& q : original)  // sorted by x, then y
    if (compare(q.point.y(), y) == Sign::zero && rank-- == 0) {
      match = &q.point;
      break;
    }
  if (!match) throw std::logic_error("point_certificate: the point is not a common point of the curves");
  for (const auto& q : original) {
    if (&q.point == match) continue;
    while (boxes_overlap(match->x(), match->y(), q.point.x(), q.point.y())) {
      match->x().refine(), match->y().refine();
      q.point.x().refine(), q.point.y().refine();
    }
  }
  return {{"exact", false},
          {"x", ax},
          {"y", ay},
          {"curves", OrderedJson::array({conic_json(A0), conic_json(B0)})},
          {"box", OrderedJson::array({OrderedJson::array({to_exact_string(match->x().lo()), to_exact_string(match->x().hi())}),
                                      OrderedJson::array({to_exact_string(match->y().lo()), to_exact_string(match->y().hi())})})}};
}

OrderedJson filter_counts_json(const oracle::FilterCounts& f) {
  const auto kind = [](std::uint64_t filtered, std::uint64_t exact) {
    return OrderedJson{{"filtered", filtered}, {"exact", exact}};
  };
  return {{"roots", kind(f.roots_filtered, f.roots_exact)},
          {"samples", kind(f.samples_filtered, f.samples_exact)},
          {"signs", kind(f.signs_filtered, f.signs_exact)},
          {"comparisons", kind(f.comparisons_filtered, f.comparisons_exact)},
          {"exact_points_built", f.exact_points}};
}

DiagramCounts diagram_counts(const Diagram& d) {
  DiagramCounts c;
  c.nodes = d.nodes.size(), c.arcs = d.arcs.size(), c.faces = d.faces.size();
  for (const auto& n : d.nodes) {
    if (n.kind == oracle::Node::Kind::voronoi) ++c.voronoi_vertices;
    if (n.sites.size() >= 2 && !n.wedged) ++c.unwedged_vertices;
  }
  for (const auto& a : d.arcs) c.unwedged_arcs += a.wedged ? 0 : 1;
  c.wedge_violations = c.unwedged_arcs + c.unwedged_vertices;
  for (const auto& f : d.faces) c.orphans += f.orphan ? 1 : 0;
  return c;
}

OrderedJson diagram_json(const Diagram& d) {
  OrderedJson vertices = OrderedJson::array();
  for (std::size_t i = 0; i < d.nodes.size(); ++i) {
    const oracle::Node& n = d.nodes[i];
    const auto [x, y] = d.original_xy(n.at);
    OrderedJson v{{"id", i},
                  {"kind", kind_name(n.kind)},
                  {"sites", n.sites},
                  {"x", x},
                  {"y", y},
                  {"on_domain_boundary", !n.boundary_edges.empty()},
                  {"domain_edges", n.boundary_edges},
                  {"wedged", n.sites.size() < 2 || n.wedged}};
    if (n.sites.size() >= 2 && !n.wedged) {
      v["unwedged_pair"] = {n.unwedged_pair.first, n.unwedged_pair.second};
      const auto [A, B] = node_curves(d, n);
      v["witness"] = point_certificate(d, n.at, A, B);
    } else {
      v["witness"] = nullptr;
    }
    vertices.push_back(std::move(v));
  }
  OrderedJson arcs = OrderedJson::array();
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    const oracle::Arc& a = d.arcs[i];
    arcs.push_back({{"id", i},
                    {"sites", {a.v, a.w}},
                    {"vertices", a.closed ? OrderedJson::array() : OrderedJson::array({a.ends[0], a.ends[1]})},
                    {"closed", a.closed},
                    {"cut_by_domain", !a.cut_by_edges.empty()},
                    {"cut_by_edges", a.cut_by_edges},
                    {"bisector", conic_json(oracle::shear_conic(a.bisector, d.shear))},
                    {"wedged", a.wedged},
                    {"witness", a.witness ? point_certificate(d, *a.witness, a.bisector, a.witness_line) : OrderedJson()}});
  }
  OrderedJson faces = OrderedJson::array();
  for (std::size_t i = 0; i < d.faces.size(); ++i) {
    const oracle::Face& f = d.faces[i];
    std::vector<int> arc_ids, pieces;
    for (int c : std::vector<int>{f.outer_cycle})
      for (int h : d.cycles[c].half_edges) {
        if (d.half_edges[h].arc >= 0) arc_ids.push_back(d.half_edges[h].arc);
        else pieces.push_back(d.half_edges[h].boundary);
      }
    faces.push_back({{"id", i},
                     {"site", f.site},
                     {"orphan", f.orphan},
                     {"boundary_arcs", arc_ids},
                     {"boundary_pieces", pieces},
                     {"holes", f.holes.size()}});
  }
  OrderedJson boundary = OrderedJson::array();
  for (const auto& b : d.boundary) boundary.push_back({{"edge", b.edge}, {"vertices", {b.from, b.to}}, {"site", b.site}});
  auto cells = [](const std::vector<oracle::DualCell>& cs, bool vertex_ids) {
    OrderedJson out = OrderedJson::array();
    for (const auto& c : cs) out.push_back(vertex_ids ? OrderedJson(c.vertex) : OrderedJson(c.sites));
    return out;
  };
  const DiagramCounts c = diagram_counts(d);
  return {{"input", {{"sites", d.input.sites.size()}, {"domain_vertices", d.input.domain.size()},
                     {"domain_corner_sites", d.corner_site},
                     {"internal_shear", to_exact_string(d.shear)}}},
          {"vertices", vertices},
          {"arcs", arcs},
          {"faces", faces},
          {"boundary_pieces", boundary},
          {"dual", {{"triangles", cells(d.dual_triangles, false)},
                    {"triangle_vertices", cells(d.dual_triangles, true)},
                    {"polygons", cells(d.dual_polygons, false)},
                    {"polygon_vertices", cells(d.dual_polygons, true)},
                    {"is_triangulation", d.dual_check.is_triangulation},
                    {"checks_run", d.dual_check.checks_run},
                    {"failures", d.dual_check.failures}}},
          {"theorem7", {{"preconditions_hold", d.theorem7.preconditions_hold},
                        {"reasons", d.theorem7.reasons},
                        {"conclusion_holds", d.dual_check.is_triangulation},
                        {"disagreement", d.theorem7.disagreement}}},
          {"counts", {{"vertices", c.voronoi_vertices}, {"nodes", c.nodes}, {"arcs", c.arcs}, {"faces", c.faces},
                      {"orphans", c.orphans}, {"wedge_violations", c.wedge_violations}}},
          {"stats", {{"boxes", d.stats.boxes}, {"leaves", d.stats.leaves}, {"max_depth", d.stats.max_depth},
                     {"candidate_triples", d.stats.triples}, {"candidate_pairs", d.stats.pairs},
                     {"candidate_points", d.stats.candidate_points},
                     {"threads", d.stats.threads},
                     {"exact_only", d.stats.exact_only},
                     {"filters", filter_counts_json(d.stats.filters)},
                     {"seconds", {{"candidates", d.stats.seconds_candidates}, {"vertices", d.stats.seconds_vertices},
                                  {"arcs", d.stats.seconds_arcs}, {"faces", d.stats.seconds_faces},
                                  {"dual", d.stats.seconds_dual}}}}}};
}

}  // namespace anisocert::io
