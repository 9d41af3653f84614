// The BWY refiner (refiners/bwy/) certified by the exact oracle on every finished run, and BWY §4.2
// checked on its traces (issue 17).
//
// BWY.R, the end state of the rules: a finished run (no rule of BWY §3.2.2 applies) is T, and the
// oracle's exact D|Ω of its sites has a dual that is a triangulation of Ω (BWY §3.2.1) equal to
// T triangle for triangle, whose triangles tile Ω (oracle_certified.hpp's assert_exact_dual:
// BWY promises no wedged arcs, and the tests do not ask for them); every segment of the PSLG is a
// union of edges; no triple of sites owns two Voronoi vertices of D|Ω (rule 4); at the oracle's
// exact Voronoi vertex of every triangle t, r² ≤ B²ℓ² for each of t's edges ℓ measured from either
// end (rule 3: r(v) ≤ Bδ(t_v)), and r ≤ size (the size rule), decided here by the oracle's signs
// of conics. Random domains (convex or not, with or without interior points and segments), smooth
// random fields (generators/fields.hpp), B from 1.2 to 3, a size bound or none; and a quarter of
// the runs with one metric on the unit square, whose grids give exact ties.
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/input.hpp"
#include "property_tests/bwy_zone.hpp"
#include "property_tests/small_angle_exemption.hpp"
#include "property_tests/generators/domains.hpp"
#include "property_tests/generators/fields.hpp"
#include "property_tests/ls_same_run.hpp"
#include "property_tests/oracle_certified.hpp"
#include "property_tests/pslg_domain.hpp"
#include "property_tests/tau_bounded_field.hpp"
#include "refiners/bwy/bwy_refiner.hpp"
#include "refiners/bwy/rules.hpp"
#include "theory/bwy_section4.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

using namespace anisocert;
using refiners::bwy::Rule;

namespace {

// The stalls refiners/common/voronoi_refinement.hpp, refiners/bwy/ and docs/refiners.md name.
bool named_stall(const std::string& why) {
  for (const char* known : {"budget", "no double point", "below 2⁻³⁰ of its length", "is undecided", "outside Ω",
                            "has no double point between them", "where a site is", "bound on boxes"})
    if (why.find(known) != std::string::npos) return true;
  return false;
}

// The oracle's node (a Voronoi vertex of D|Ω) that owns the three sites of t.
const oracle::Node& node_of(const oracle::Diagram& d, const std::array<int, 3>& t) {
  const auto owns = [&t](const oracle::Node& n) {
    return n.kind == oracle::Node::Kind::voronoi &&
           std::all_of(t.begin(), t.end(), [&n](int k) { return std::binary_search(n.sites.begin(), n.sites.end(), k); });
  };
  const auto node = std::find_if(d.nodes.begin(), d.nodes.end(), owns);
  RC_ASSERT(node != d.nodes.end());
  return *node;
}

// The sign at the oracle's node of d_a(x)² − R², a the mesh's site k (in the oracle's sheared
// coordinates, where distances are those of the input: oracle/diagram/input.hpp).
Sign radius_beyond(const oracle::Diagram& d, const oracle::Node& n, int k, const Rational& R2) {
  oracle::Conic q = oracle::distance_conic(d.sheared.sites[static_cast<std::size_t>(k)], d.sheared.metrics[static_cast<std::size_t>(k)]);
  q.f -= R2;
  return n.at.sign_of(q);
}

Rational d2_from(const geometry::Mesh<Rational>& m, int p, int q) {
  return gen::d2(m.metrics[static_cast<std::size_t>(p)], m.sites[static_cast<std::size_t>(p)], m.sites[static_cast<std::size_t>(q)]);
}

}  // namespace

RC_GTEST_PROP(BWY_R, FinishedRunsAreTheExactDualAndNoRuleApplies, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  // A quarter of the runs take the degenerate case instead: one metric, diag(m, m) or diag(m, 4m)
  // on the unit square, whose grids of sites are cocircular (exact ties: Voronoi vertices of
  // degree 4 or more, whose fans enter T).
  const bool one_metric = *rc::gen::inRange(0, 4) == 0;
  const double scale = *rc::gen::elementOf(std::vector<double>{16, 64, 256});
  const fields::MetricField field =
      one_metric ? fields::make_field("constant", {{"m11", scale}, {"m22", *rc::gen::arbitrary<bool>() ? scale : 4 * scale}}) : f.field();
  const bool reflex = *rc::gen::arbitrary<bool>();
  const refiners::common::Domain domain =
      gen::domain_with_interior(one_metric ? std::vector<predicates::Point2<double>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}} : gen::random_domain(reflex, false));
  RC_TAG(one_metric ? "one metric, the unit square" : reflex ? "non-convex" : "convex");
  refiners::bwy::BwyParameters p;
  p.shape_bound = *rc::gen::elementOf(std::vector<double>{1.2, 1.5, 2, 3});
  p.size = *rc::gen::elementOf(std::vector<double>{0, 1, 2, 4});
  p.max_vertices = 250, p.max_seconds = 5;
  // Half the runs insert at off-centres (issue 41): where a site goes is a choice, and what a
  // finished run guarantees (below) must not depend on it.
  p.off_centres = *rc::gen::arbitrary<bool>();
  RC_TAG(p.off_centres ? "off-centres" : "at Voronoi vertices");
  const auto r = refiners::bwy::refine_bwy(domain, field, p);
  if (!r.consistent) {
    RC_LOG() << r.stop_reason << "\n";
    RC_TAG(r.stop_reason.find("budget") != std::string::npos ? "stopped: budget" : "stopped: " + r.stop_reason.substr(0, 40));
    RC_ASSERT(named_stall(r.stop_reason));
    return;
  }
  RC_TAG("finished");
  RC_ASSERT(r.encroached_left == 0u && r.unedged_left == 0u && r.violators_left == 0u && r.embedding_failure.empty());
  const auto certified = gen::assert_exact_dual(r.mesh);
  if (!certified) return;
  const geometry::Mesh<Rational>& m = certified->mesh;
  const oracle::Diagram& d = certified->diagram;
  for (std::size_t k = 0; k < r.mesh.sites.size(); ++k) {
    const auto M = field.at(r.mesh.sites[k].x, r.mesh.sites[k].y), written = r.mesh.metrics[k];
    RC_ASSERT(written.m11 == M.m11 && written.m12 == M.m12 && written.m22 == M.m22);
  }
  gen::assert_pslg_segments_are_edges(m, domain);
  std::map<std::vector<int>, int> owners;  // rule 4
  for (const auto& n : d.nodes)
    if (n.kind == oracle::Node::Kind::voronoi && n.sites.size() == 3) RC_ASSERT(++owners[n.sites] == 1);
  const Rational B2 = Rational(p.shape_bound) * Rational(p.shape_bound), size2 = Rational(p.size) * Rational(p.size);
  std::size_t exempt = 0;  // badly shaped across a small input angle, which rule 3 leaves (corner_shells.hpp)
  for (const auto& t : r.mesh.triangles) {
    const oracle::Node& n = node_of(d, t);
    bool bad = false;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != j) bad = bad || radius_beyond(d, n, t[0], B2 * d2_from(m, t[i], t[j])) == Sign::positive;  // rule 3
    if (bad) {
      RC_ASSERT(n.sites.size() == 3u && gen::exempt_at_small_angle(m, domain, t));
      ++exempt;
    }
    if (p.size > 0) RC_ASSERT(radius_beyond(d, n, t[0], size2) != Sign::positive);
  }
  RC_ASSERT(exempt == r.exempt_left);
  RC_CLASSIFY(exempt > 0, "triangles left at a small input angle");
  RC_CLASSIFY(r.mesh.sites.size() > 50, "more than 50 sites");
  RC_CLASSIFY(std::any_of(d.nodes.begin(), d.nodes.end(), [](const oracle::Node& n) { return n.sites.size() > 3; }),
              "a Voronoi vertex of degree 4 or more");
}

// The trace: the k-th entry is the k-th inserted site, at its place exactly; its rule is one of
// rules.hpp's; a site at a Voronoi vertex (rules 3–6) has a positive radius and a split (rules 1,
// 2, 7) none; only rule 7's splits name the rule of the point that would have encroached, and
// that rule is one of 2–6 or the island's.
RC_GTEST_PROP(BwyRefiner, TraceRecordsEveryInsertion, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  refiners::bwy::BwyParameters p;
  p.size = *rc::gen::elementOf(std::vector<double>{0, 1, 2});
  p.max_vertices = 120, p.max_seconds = 1e9;
  const refiners::common::Domain domain = gen::domain_with_interior(gen::random_domain(*rc::gen::arbitrary<bool>(), false));
  const auto r = refiners::bwy::refine_bwy(domain, f.field(), p);
  const std::size_t first = domain.vertices().size();
  RC_ASSERT(first + r.trace.size() == r.mesh.sites.size());
  for (std::size_t i = 0; i < r.trace.size(); ++i) {
    const auto& e = r.trace[i];
    RC_ASSERT(e.x == r.mesh.sites[first + i].x && e.y == r.mesh.sites[first + i].y);
    RC_ASSERT(e.rule >= 1 && e.rule <= 10);
    const Rule rule = static_cast<Rule>(e.rule);
    const bool split = rule == Rule::encroached_segment || rule == Rule::not_an_edge || rule == Rule::split_instead || rule == Rule::corner_shell;
    const bool at_vertex = rule == Rule::bad_shape || rule == Rule::several_vertices || rule == Rule::overlap || rule == Rule::too_large;
    if (split) RC_ASSERT(e.radius == 0);
    if (at_vertex) RC_ASSERT(e.radius > 0);
    RC_ASSERT((e.for_rule != 0) == (rule == Rule::split_instead));
    if (e.for_rule != 0) RC_ASSERT((e.for_rule >= 3 && e.for_rule <= 6) || e.for_rule == 8 || e.for_rule == 9);
    RC_ASSERT(e.nearest_distance > 0);
  }
  RC_TAG(r.trace.size() < 40 ? "under 40 insertions" : "40 insertions or more");
}

// The filters only speed up (DESIGN.md): with BwyParameters::filters off, the segment tests are
// decided in rationals alone, and the run makes the same insertions and ends with the same mesh.
RC_GTEST_PROP(BWY_Filters, FilteredRunIsTheExactRun, ()) {
  const gen::SmoothField f = gen::random_smooth_field();
  refiners::bwy::BwyParameters p;
  p.shape_bound = *rc::gen::elementOf(std::vector<double>{1.5, 2});
  p.size = *rc::gen::elementOf(std::vector<double>{0, 1, 2, 4});
  p.max_vertices = 120, p.max_seconds = 1e9;
  const refiners::common::Domain domain = gen::domain_with_interior(gen::random_domain(*rc::gen::arbitrary<bool>(), false));
  const auto filtered = refiners::bwy::refine_bwy(domain, f.field(), p);
  p.filters = false;
  const auto exact = refiners::bwy::refine_bwy(domain, f.field(), p);
  RC_TAG(filtered.consistent ? "finished" : "stopped");
  gen::assert_same_run(filtered, exact);
}

// BWY §4.2 on the traces of runs whose field has distortion at most G between any two points (one
// metric, or two metrics on and off a disc within τ ≤ G decided exactly: tau_bounded_field.hpp),
// so that bdr_min(G) = ∞, with no size rule, B in {1.42, 1.5, 2} and G the largest of Lemma 2 for B
// (all four of §4.2's conditions then hold: G²√(G²+1) ≤ 1.4196 for B = 1.42). Then
//   Lemma 2 holds for every two adjacent triangles whose radius-edge ratios are at most B: their
//     Voronoi edges near them are wedged, and they do not overlap. Rules 4 and 5 act only when no
//     vertex is badly shaped (rule 3 comes first), so they never fire: asserted.
//   Every insertion keeps §4.2's minimal inter-distance: with m the least d(u, v) = min{d_u(v),
//     d_v(u)} between two sites before it (at most the paper's d_min, which is over adjacent sites)
//     and lfs_min ≥ δ/2 (δ the least distance between two non-adjacent edges in the field's
//     metrics, as in LS_T11), the new site's d to every earlier one is at least
//     min(m/(G²√(G⁴−1)), Bm/(G²√(G²+1)), lfs_min/G); the bdr term is ∞. The domains are combs
//     (narrow slots, right angles; diagonal metrics) and random polygons whose adjoining edges are
//     at least 2 arcsin(G²/2) (about 60°) apart in their corner's metric, decided exactly: LS
//     Theorem 11's separation, which the lfs_min argument BWY takes from LS needs (with sharper
//     corners in the metric, splits run into the corner: seen here). Rules 8 and 9 (island,
//     unresolved) are not BWY's; their sites are counted, not checked. A site at a Voronoi vertex
//     is the vertex rounded, within the trace's displacement e: the comparison, in long double,
//     allows √λ_max·e and a relative 10⁻¹².
namespace {

// A run of the BWY refiner on a field of distortion at most G everywhere (BWY_S42 and BWY_L2 below).
struct BoundedDistortionRun {
  refiners::bwy::BwyParameters p;
  gen::TauBoundedField field;
  Rational delta2;  // δ², the least over the field's metrics of the distance between non-adjacent edges
  refiners::bwy::BwyResult r;
};

BoundedDistortionRun bounded_distortion_run() {
  BoundedDistortionRun run;
  refiners::bwy::BwyParameters& p = run.p;
  p.shape_bound = *rc::gen::elementOf(std::vector<double>{1.42, 1.5, 2});
  p.size = 0;
  p.max_vertices = 3000, p.max_seconds = 1e9;
  const Rational B(p.shape_bound);
  p.distortion = theory::bwy_lemma2_gamma_max(B, 128).lower_double();
  const Rational G(p.distortion);
  const int kind = *rc::gen::inRange(0, 3);
  const auto corners = kind == 0 ? gen::random_comb() : gen::random_domain(kind == 2, true);
  run.field = gen::tau_bounded_field(corners, kind == 0, G * G);
  std::vector<predicates::Point2<Rational>> q;
  for (const auto& v : corners) q.push_back({Rational(v.x), Rational(v.y)});
  const std::size_t n = corners.size();
  const Rational G4 = G * G * G * G;
  for (std::size_t k = 0; k < n; ++k) {  // the corners' separation of LS Theorem 11, 2 arcsin(G²/2) (about 60°)
    const auto &before = q[(k + n - 1) % n], &at = q[k], &after = q[(k + 1) % n];
    RC_PRE(gen::cos_at_most(gen::exact(run.field.field.at(corners[k].x, corners[k].y)), before.x - at.x, before.y - at.y, after.x - at.x,
                            after.y - at.y, 1 - G4 / 2));
  }
  std::optional<Rational> delta2;
  for (const auto& M : run.field.metrics)
    if (const auto dd = gen::nonadjacent_edges_distance2(gen::exact(M), q); dd && (!delta2 || *dd < *delta2)) delta2 = dd;
  RC_PRE(delta2.has_value());  // a triangle: no bound on lfs_min here
  run.delta2 = *delta2;
  RC_TAG(kind == 0 ? "comb" : kind == 2 ? "non-convex" : "convex", run.field.kind);
  run.r = refiners::bwy::refine_bwy(refiners::common::Domain(corners), run.field.field, p);
  RC_LOG() << run.r.stop_reason << "\n";
  for (const auto& c : corners) RC_LOG() << "corner " << c.x << " " << c.y << "\n";
  RC_ASSERT(run.r.consistent);
  return run;
}

}  // namespace

RC_GTEST_PROP(BWY_S42, EveryInsertionKeepsTheMinimalInterdistance, ()) {
  const BoundedDistortionRun run = bounded_distortion_run();
  const auto& p = run.p;
  const auto& field = run.field;
  const auto& r = run.r;
  for (const auto& [name, count] : r.rule_counts)
    if (name == "several vertices" || name == "overlap") RC_ASSERT(count == 0u);
  for (const auto& t : r.trace) RC_ASSERT(t.for_rule != 4 && t.for_rule != 5);  // nor splits made for them
  const long double g = p.distortion, b = p.shape_bound;
  const long double violator = 1 / (g * g * std::sqrt(g * g * g * g - 1)), shape = b / (g * g * std::sqrt(g * g + 1));
  const long double lfs = std::sqrt(static_cast<long double>(run.delta2.convert_to<double>())) / 2 / g * (1 - 1e-12L);
  long double lmax = 0;  // √λ_max bounds the M-length of a Euclidean unit vector
  for (const auto& M : field.metrics) lmax = std::max(lmax, (static_cast<long double>(M.m11) + M.m22) * (1 + 1e-15L));
  const auto& sites = r.mesh.sites;
  const std::size_t first = sites.size() - r.trace.size();
  const auto dist = [&](std::size_t u, std::size_t v) {
    const auto one = [&](const predicates::Sym2<double>& M) {
      const long double dx = static_cast<long double>(sites[u].x) - sites[v].x, dy = static_cast<long double>(sites[u].y) - sites[v].y;
      return M.m11 * dx * dx + 2 * M.m12 * dx * dy + M.m22 * dy * dy;
    };
    return std::sqrt(std::min(one(r.mesh.metrics[u]), one(r.mesh.metrics[v])));
  };
  long double m = INFINITY;
  for (std::size_t u = 0; u < first; ++u)
    for (std::size_t v = u + 1; v < first; ++v) m = std::min(m, dist(u, v));
  std::size_t checked = 0, other = 0;
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    const auto& t = r.trace[k];
    const std::size_t z = first + k;
    long double nearest = INFINITY;
    for (std::size_t w = 0; w < z; ++w) nearest = std::min(nearest, dist(z, w));
    RC_LOG() << "insertion " << k << " rule " << t.rule << " for " << t.for_rule << ": nearest " << nearest << ", m " << m << "\n";
    if (t.rule == 8 || t.rule == 9 || t.for_rule == 8 || t.for_rule == 9) {
      ++other;
    } else {
      const long double e = std::sqrt(lmax) * t.displacement;
      RC_ASSERT(nearest >= (std::min({violator * m, shape * m, lfs}) - e) * (1 - 1e-12L));
      ++checked;
    }
    m = std::min(m, nearest);
  }
  RC_CLASSIFY(checked > 20, "more than 20 insertions checked");
  RC_CLASSIFY(other > 0, "island or unresolved sites (not checked)");
}

// BWY Lemma 2 on final meshes: the runs of BWY_S42 (distortion at most the run's G between any two
// points, so γ ≤ G for every two adjacent triangles, whose radius-edge ratios are at most B:
// BWY_R). For up to six pairs of adjacent triangles abc, abd of each mesh, the exact diagram of
// {a, b, c, d} restricted to a rational polygon P ⊆ Z (bwy_zone.hpp: inscribed in the balls
// B(x, 5Bδ) of the four sites, δ = max(δ(abc), δ(abd)) exactly, d(p, q) = min(d_p, d_q); 5 ≤ 1 + 4γ)
// has every arc wedged. A pair whose four sites are not all inside P (the inscribed polygons are a
// little smaller than the balls) is counted and skipped.
RC_GTEST_PROP(BWY_L2, AdjacentTrianglesOfFinalMeshesHaveWedgedArcsInTheirZone, ()) {
  const BoundedDistortionRun run = bounded_distortion_run();
  const auto& mesh = run.r.mesh;
  const geometry::Mesh<Rational> m = geometry::exact(mesh);
  std::map<std::pair<int, int>, std::vector<int>> on_edge;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = mesh.triangles[t][static_cast<std::size_t>(i)], b = mesh.triangles[t][static_cast<std::size_t>((i + 1) % 3)];
      on_edge[std::minmax(a, b)].push_back(static_cast<int>(t));
    }
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [e, ts] : on_edge)
    if (ts.size() == 2) pairs.emplace_back(ts[0], ts[1]);
  RC_PRE(!pairs.empty());
  const auto d2 = [&](int u, int v) { return std::min(d2_from(m, u, v), d2_from(m, v, u)); };
  const auto shortest2 = [&](const std::array<int, 3>& t) { return std::min({d2(t[0], t[1]), d2(t[1], t[2]), d2(t[0], t[2])}); };
  const Rational B(run.p.shape_bound);
  int checked = 0, skipped = 0;
  for (int k = 0; k < 6; ++k) {
    const auto [t1, t2] = pairs[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(pairs.size())))];
    const auto &T1 = mesh.triangles[static_cast<std::size_t>(t1)], &T2 = mesh.triangles[static_cast<std::size_t>(t2)];
    std::vector<int> four(T1.begin(), T1.end());
    for (int v : T2)
      if (std::find(four.begin(), four.end(), v) == four.end()) four.push_back(v);
    RC_ASSERT(four.size() == 4u);
    const Rational r2 = 25 * B * B * std::max(shortest2(T1), shortest2(T2));
    std::vector<predicates::Point2<Rational>> P;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto ball = gen::inscribed_ball(m.sites[static_cast<std::size_t>(four[i])], m.metrics[static_cast<std::size_t>(four[i])], r2);
      P = i == 0 ? ball : gen::clip(P, ball);
    }
    const auto inside = [&P](const predicates::Point2<Rational>& x) {
      for (std::size_t e = 0; e < P.size(); ++e) {
        const auto &a = P[e], &b = P[(e + 1) % P.size()];
        if ((b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x) <= 0) return false;
      }
      return P.size() >= 3;
    };
    if (!std::all_of(four.begin(), four.end(), [&](int v) { return inside(m.sites[static_cast<std::size_t>(v)]); })) {
      ++skipped;
      continue;
    }
    geometry::Mesh<Rational> zone;
    for (int v : four) {
      zone.sites.push_back(m.sites[static_cast<std::size_t>(v)]);
      zone.metrics.push_back(m.metrics[static_cast<std::size_t>(v)]);
    }
    zone.domain = P;
    const oracle::Diagram d = oracle::compute_diagram(zone);
    for (const auto& arc : d.arcs) RC_ASSERT(arc.wedged);
    ++checked;
  }
  RC_ASSERT(checked > 0);
  RC_CLASSIFY(checked == 6, "six pairs checked");
  RC_CLASSIFY(skipped > 0, "a pair skipped (a site outside P)");
}
