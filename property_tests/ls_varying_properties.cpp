// The Labelle–Shewchuk refiner on fields whose sites have different metrics (refiners/ls/ls_varying)
// certified by the exact oracle on every finished run (issue 16).
//
// LS.S9: a finished run (no encroached subsegment, no violator) is the dual of the exact diagram:
// the oracle's D|Ω of the final sites has no orphans, every arc and vertex wedged, Theorem 7's
// preconditions, a dual that is a triangulation of Ω and equals the mesh triangle for triangle;
// every angle is at least θ_bound in the metric of each of the triangle's three vertices and in
// the field's at its Voronoi vertex, decided here exactly; every Voronoi vertex of D|Ω is within `size` of each of its three sites in the
// field's metric at that site, decided exactly at the oracle's vertex; every segment of the PSLG
// is a union of mesh edges (decided from the domain). Random domains (convex or not, with or without interior points and segments), smooth
// random fields (generators/fields.hpp, mild and strong), θ_bound from 5° to 21° in tenths (tagged by Theorem 11's
// separation at the corners, in the field's metrics there), a size bound or none; half the runs in LS §9's variation
// (--normalized-metric), whose mesh metrics must be M′ = det(M)^(−1/2) M (fields/normalized.hpp) at
// every site, the field's M elsewhere. A stopped run names its budget or a stall the refiner documents.
#include "fields/normalized.hpp"
#include "geometry/mesh.hpp"
#include "predicates/angle.hpp"
#include "oracle/diagram/input.hpp"
#include "property_tests/ls_same_run.hpp"
#include "property_tests/oracle_certified.hpp"
#include "property_tests/small_angle_exemption.hpp"
#include "property_tests/theta_bound.hpp"
#include "property_tests/pslg_domain.hpp"
#include "property_tests/generators/domains.hpp"
#include "property_tests/generators/fields.hpp"
#include "refiners/ls/ls_refiner.hpp"
#include "refiners/ls/rules.hpp"
#include "refiners/ls/theorem11_conditions.hpp"
#include "theory/ls_theorem11.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>

using namespace anisocert;

namespace {

// The stalls refiners/ls/ls_varying.hpp and docs/refiners.md name.
bool named_stall(const std::string& why) {
  for (const char* known : {"budget", "no double point", "below 2⁻³⁰ of its length", "is undecided", "tangentially", "outside Ω",
                            "has no double point between them", "where a site is", "bound on boxes"})
    if (why.find(known) != std::string::npos) return true;
  return false;
}

// d_a(x)² − size² in the metric M, as a conic in x.
oracle::Conic beyond_size(const predicates::Point2<Rational>& a, const predicates::Sym2<double>& metric, double size) {
  const Rational m11(metric.m11), m12(metric.m12), m22(metric.m22), s(size);
  return {m11, 2 * m12, m22, -2 * (m11 * a.x + m12 * a.y), -2 * (m12 * a.x + m22 * a.y),
          m11 * a.x * a.x + 2 * m12 * a.x * a.y + m22 * a.y * a.y - s * s};
}

}  // namespace

RC_GTEST_PROP(LS_S9, VaryingFieldRunsAreTheDualOfTheExactDiagram, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  const bool reflex = *rc::gen::arbitrary<bool>();
  const auto corners = gen::random_domain(reflex, false);
  RC_TAG(reflex ? "non-convex" : "convex");
  refiners::ls::LsParameters p;
  p.theta_bound = *gen::theta_in_tenths(50, 210);  // 5° to 21°: Theorem 11's range (to 20.7048°) and a little beyond
  p.size = *rc::gen::elementOf(std::vector<double>{0, 1, 2, 4});
  p.max_vertices = 250, p.max_seconds = 5;
  p.normalized_metric = *rc::gen::arbitrary<bool>();
  RC_TAG(p.normalized_metric ? "normalized metric" : "metric");
  p.off_centres = *rc::gen::arbitrary<bool>();  // a choice of where to insert (issue 41): the guarantees below must not depend on it
  RC_TAG(p.off_centres ? "off-centres" : "at Voronoi vertices");
  const refiners::common::Domain domain = gen::domain_with_interior(corners);
  std::vector<predicates::Sym2<double>> at_vertices;
  for (const auto& v : domain.vertices()) at_vertices.push_back(f.at(v.x, v.y));
  const auto t11 = refiners::ls::theorem11_conditions(domain, at_vertices, p.theta_bound);
  RC_TAG(!t11.theta_admissible ? "theta_bound above Theorem 11's" : t11.corners_failing.empty() ? "separation holds" : "separation fails");
  const refiners::ls::LsResult r = refiners::ls::refine_ls(domain, f.field(), p);
  if (!r.consistent) {
    RC_LOG() << r.stop_reason << "\n";
    RC_TAG(r.stop_reason.find("time budget") != std::string::npos ? "stopped: time" : r.stop_reason.find("budget") != std::string::npos ? "stopped: vertices" : "stopped: " + r.stop_reason.substr(0, 40));
    RC_ASSERT(named_stall(r.stop_reason));
    return;
  }
  RC_TAG("finished");
  const auto certified = gen::assert_dual_of_exact_diagram(r.mesh);
  if (!certified) return;
  const geometry::Mesh<Rational>& m = certified->mesh;

  for (std::size_t k = 0; k < r.mesh.sites.size(); ++k) {
    const auto M = f.at(r.mesh.sites[k].x, r.mesh.sites[k].y), written = r.mesh.metrics[k];
    const auto want = p.normalized_metric ? fields::normalized(M) : M;
    RC_ASSERT(written.m11 == want.m11 && written.m12 == want.m12 && written.m22 == want.m22);
  }
  if (p.size > 0)
    for (const auto& node : certified->diagram.nodes)
      if (node.kind == oracle::Node::Kind::voronoi)
        for (int k : node.sites)  // the oracle's points are in its sheared coordinates x' = x + s·y (oracle/diagram/input.hpp)
          RC_ASSERT(node.at.sign_of(oracle::shear_conic(beyond_size(m.sites[k], f.at(r.mesh.sites[k].x, r.mesh.sites[k].y), p.size),
                                                        -certified->diagram.shear)) != Sign::positive);

  // Every angle is at least θ_bound, but in the triangles across a small input angle, which rule 3
  // leaves (corner_shells.hpp) and the run counts.
  const Rational s2 = gen::sin2_above(p.theta_bound);
  std::size_t exempt = 0;
  const oracle::Diagram& d = certified->diagram;
  for (const auto& t : r.mesh.triangles) {
    bool poor = false;
    for (int i = 0; i < 3; ++i)
      for (int k : t)  // in the metric of each vertex
        poor = poor || !predicates::angle_at_least_arcsin(m.sites[t[(i + 2) % 3]], m.sites[t[i]], m.sites[t[(i + 1) % 3]], m.metrics[k], s2);
    // … and in the field's metric at the triangle's Voronoi vertex (of degree 3, or an exact tie's),
    // as the refiner judges it: the field at the middle of the oracle's box of the vertex, unsheared
    // in intervals, as the refiner takes the middle of its own certified box. Both boxes are a few
    // ulps wide, so the two points can differ in their last bits, and an angle within about 10⁻¹⁵
    // of θ_bound could be judged differently by the two; none was (2,000 runs).
    const auto owns = [&t](const oracle::Node& n) {
      return n.kind == oracle::Node::Kind::voronoi &&
             std::all_of(t.begin(), t.end(), [&n](int k) { return std::binary_search(n.sites.begin(), n.sites.end(), k); });
    };
    const auto node = std::find_if(d.nodes.begin(), d.nodes.end(), owns);
    RC_ASSERT(node != d.nodes.end());
    const FilterInterval X = node->at.x - FilterInterval::around(d.shear) * node->at.y;
    const auto F = f.at(X.lo / 2 + X.hi / 2, node->at.y.lo / 2 + node->at.y.hi / 2);
    const predicates::Sym2<Rational> M{Rational(F.m11), Rational(F.m12), Rational(F.m22)};
    for (int i = 0; i < 3; ++i)
      poor = poor || !predicates::angle_at_least_arcsin(m.sites[t[(i + 2) % 3]], m.sites[t[i]], m.sites[t[(i + 1) % 3]], M, s2);
    if (poor) {
      RC_ASSERT(gen::exempt_at_small_angle(m, domain, t));
      ++exempt;
    }
  }
  RC_ASSERT(exempt == r.exempt_left);
  RC_CLASSIFY(exempt > 0, "triangles left at a small input angle");
  gen::assert_pslg_segments_are_edges(m, domain);
}

// The trace (issue 16: "the trace records every insertion (rule, point, distances)"): the k-th
// entry is the k-th inserted site, at its place exactly; its distance is the nearest earlier
// site's in the new site's metric (the diagram's: M′ with --normalized-metric), by brute force
// here in long double against the refiner's grid search; the rule is one of rules.hpp's, a
// violator's radius is positive and a split's zero; only rule 2's splits name the rule of the
// point that would have encroached.
RC_GTEST_PROP(LsRefiner, TraceRecordsEveryInsertionWithItsNearestSite, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  refiners::ls::LsParameters p;
  p.theta_bound = *gen::theta_in_tenths(50, 210);
  p.size = *rc::gen::elementOf(std::vector<double>{0, 1, 2});
  p.normalized_metric = *rc::gen::arbitrary<bool>();
  p.max_vertices = 120, p.max_seconds = 1e9;
  const refiners::common::Domain domain = gen::domain_with_interior(gen::random_domain(*rc::gen::arbitrary<bool>(), false));
  const auto r = refiners::ls::refine_ls(domain, f.field(), p);
  const auto& sites = r.mesh.sites;
  const std::size_t first = domain.vertices().size();  // X's vertices are the first sites, then one per entry
  RC_ASSERT(first + r.trace.size() == sites.size());
  using Rule = refiners::ls::Rule;
  for (std::size_t i = 0; i < r.trace.size(); ++i) {
    const auto& e = r.trace[i];
    const std::size_t z = first + i;
    RC_ASSERT(e.x == sites[z].x && e.y == sites[z].y);
    const auto& M = r.mesh.metrics[z];
    long double least = INFINITY;
    for (std::size_t w = 0; w < z; ++w) {
      const long double dx = static_cast<long double>(sites[w].x) - sites[z].x, dy = static_cast<long double>(sites[w].y) - sites[z].y;
      least = std::min(least, dx * dx * M.m11 + 2 * dx * dy * M.m12 + dy * dy * M.m22);
    }
    const long double recorded = static_cast<long double>(e.nearest_distance) * e.nearest_distance;
    RC_ASSERT(std::abs(recorded - least) <= 1e-12L * least);
    const Rule rule = static_cast<Rule>(e.rule);
    RC_ASSERT(std::find(refiners::ls::rules_by_priority.begin(), refiners::ls::rules_by_priority.end(), rule) != refiners::ls::rules_by_priority.end());
    const bool split = rule == Rule::encroached_segment || rule == Rule::violator_encroaches || rule == Rule::corner_shell;
    const bool at_vertex = rule == Rule::poor_angle || rule == Rule::too_large || rule == Rule::inverted || rule == Rule::unwedged;
    if (split) RC_ASSERT(e.radius == 0);
    if (at_vertex) RC_ASSERT(e.radius > 0);
    RC_ASSERT((e.for_rule != 0) == (rule == Rule::violator_encroaches));
  }
  RC_TAG(r.trace.size() < 40 ? "under 40 insertions" : "40 insertions or more");
}

// The filters only speed up (DESIGN.md): with LsParameters::filters off, encroachment along
// subsegments (segment_quadratics.hpp's `reaches`) is decided in rationals alone, and the run
// must make the same insertions and end with the same mesh, double for double.
RC_GTEST_PROP(LS_Filters, VaryingFieldFilteredRunIsTheExactRun, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  const auto corners = gen::random_domain(*rc::gen::arbitrary<bool>(), false);
  refiners::ls::LsParameters p;
  p.theta_bound = *rc::gen::elementOf(std::vector<double>{5, 10, 15, 20});
  p.size = *rc::gen::elementOf(std::vector<double>{0, 1, 2, 4});
  p.normalized_metric = *rc::gen::arbitrary<bool>();
  p.max_vertices = 120, p.max_seconds = 1e9;
  const refiners::common::Domain domain = gen::domain_with_interior(corners);
  const auto filtered = refiners::ls::refine_ls(domain, f.field(), p);
  p.filters = false;
  const auto exact = refiners::ls::refine_ls(domain, f.field(), p);
  RC_TAG(filtered.consistent ? "finished" : "stopped");
  gen::assert_same_run(filtered, exact);
}
