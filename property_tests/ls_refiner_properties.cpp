// The Labelle–Shewchuk refiner (refiners/ls/) certified by the exact oracle on every finished run
// (issue 16). Constant fields only so far: the refiner keeps the diagram of one metric.
//
// LS.T11 (the T part, constant fields): with θ_bound < arcsin(1/(2√2)), no size rule and every
// pair of adjoining segments at least 2 arcsin(γ²/2) apart in the metric (decided here exactly),
// the run finishes, and every two sites are at least μ = lfs_min/γ apart (bdr = ∞ for one metric).
// lfs_min from below: with τ ≡ 1 every two adjacent edges of Ω are intertwined (LS Definition 5),
// so non-intertwined feature points lie on non-adjacent edges, and a disc touching both has a
// diameter of at least their M-distance: lfs_min ≥ δ/2, δ the least M-distance between two
// non-adjacent edges (a rational; the assertion d² ≥ δ²/(4γ_hi²) is the theorem's, weakened only
// by γ's enclosure and this bound). The sites then also obey the packing count of LS's proof.
//
// LS.S9: a finished run (no encroached subsegment, no violator) is the dual of the exact diagram:
// the oracle's D|Ω of the final sites has no orphans, every arc and vertex wedged, Theorem 7's
// preconditions, a dual that is a triangulation of Ω and equals the mesh triangle for triangle;
// every angle is at least θ_bound and every circumradius at most `size` in the metric, decided
// exactly by closed forms here (not by the refiner's code); every subsegment is a mesh edge.
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "predicates/angle.hpp"
#include "property_tests/generators/domains.hpp"
#include "property_tests/generators/metrics.hpp"
#include "property_tests/ls_same_run.hpp"
#include "property_tests/oracle_certified.hpp"
#include "refiners/ls/ls_refiner.hpp"
#include "refiners/ls/theorem11_conditions.hpp"
#include "theory/ls_theorem11.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

using namespace anisocert;

namespace {

struct Run {
  refiners::ls::LsParameters p;
  refiners::ls::LsResult r;
  predicates::Sym2<double> M;
  std::string domain, separation;
};

// A random constant metric (eigenvalues 1 to 100, or with a ratio up to 10², any orientation; a
// diagonal one on combs), a random domain (convex or not, with or without acute corners, or a comb
// with narrow slots), θ_bound from 5° to 30° (above 20.7° Theorem 11 gives no guarantee) and a size
// bound or none.
Run random_run() {
  Run run;
  const int kind = *rc::gen::inRange(0, 5);
  const bool reflex = kind % 2 == 1, obtuse = kind < 2;
  const auto corners = kind == 4 ? gen::random_comb() : gen::random_domain(reflex, obtuse);
  run.domain = kind == 4 ? "comb" : std::string(reflex ? "non-convex" : "convex") + (obtuse ? "" : ", acute corners allowed");
  const double l1 = *rc::gen::inRange(1, 101);
  const double l2 = *rc::gen::arbitrary<bool>() ? *rc::gen::inRange(1, 101) : l1 * std::pow(10.0, *rc::gen::inRange(1, 3));
  const double angle = kind == 4 ? 0 : *rc::gen::inRange(0, 180) * M_PI / 180;
  const double c = std::cos(angle), s = std::sin(angle);
  run.M = {l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c};
  run.p.theta_bound = *rc::gen::elementOf(std::vector<double>{5, 10, 15, 20, 20.5, 25, 30});
  run.p.size = *rc::gen::elementOf(std::vector<double>{0, 0, 0.5, 1, 2});
  run.p.max_vertices = 400, run.p.max_seconds = 1e9;
  const refiners::common::Domain domain(corners);
  const auto field = fields::make_field("constant", {{"m11", run.M.m11}, {"m12", run.M.m12}, {"m22", run.M.m22}});
  run.r = refiners::ls::refine_ls(domain, field, run.p);
  const auto t11 = refiners::ls::theorem11_conditions(domain, std::vector(corners.size(), run.M), run.p.theta_bound);
  run.separation = !t11.theta_admissible             ? "theta_bound above Theorem 11's"
                   : t11.corners_failing.empty() ? "separation holds"
                                                 : "separation fails";
  return run;
}

// sin²θ_bound from above, as a rational: "angle ≥ arcsin √s2" proves "angle ≥ θ_bound".
Rational sin2_above(double theta) {
  const Interval s = theory::ls_t11_sin_theta(rational_from_double(theta), 256);
  return rational_from_double(sqr(s).upper_double());
}

using gen::d2;

// The squared M-distance from p to the segment ab (exact: the clamped projection).
Rational d2_to_segment(const predicates::Sym2<Rational>& M, const predicates::Point2<Rational>& p, const predicates::Point2<Rational>& a,
                       const predicates::Point2<Rational>& b) {
  const auto dot = [&](const Rational& x1, const Rational& y1, const Rational& x2, const Rational& y2) {
    return M.m11 * x1 * x2 + M.m12 * (x1 * y2 + y1 * x2) + M.m22 * y1 * y2;
  };
  const Rational ux = b.x - a.x, uy = b.y - a.y;
  const Rational t = std::clamp(dot(p.x - a.x, p.y - a.y, ux, uy) / dot(ux, uy, ux, uy), Rational(0), Rational(1));
  return d2(M, p, {a.x + t * ux, a.y + t * uy});
}

// δ², the least squared M-distance between two non-adjacent edges of the polygon q (the closest
// points of two disjoint segments include an endpoint); nothing for a triangle.
std::optional<Rational> nonadjacent_edges_distance2(const predicates::Sym2<Rational>& M, const std::vector<predicates::Point2<Rational>>& q) {
  const std::size_t n = q.size();
  std::optional<Rational> delta2;
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t f = e + 2; f < n; ++f) {
      if ((f + 1) % n == e) continue;  // adjacent through corner e
      const auto &a = q[e], &b = q[(e + 1) % n], &c = q[f], &d = q[(f + 1) % n];
      for (const Rational& x : {d2_to_segment(M, a, c, d), d2_to_segment(M, b, c, d), d2_to_segment(M, c, a, b), d2_to_segment(M, d, a, b)})
        if (!delta2 || x < *delta2) delta2 = x;
    }
  return delta2;
}

// cos∠(u, v) <= k in M, exactly (u, v non-zero).
bool cos_at_most(const predicates::Sym2<Rational>& M, const Rational& ux, const Rational& uy, const Rational& vx, const Rational& vy,
                 const Rational& k) {
  const Rational uv = M.m11 * ux * vx + M.m12 * (ux * vy + uy * vx) + M.m22 * uy * vy;
  const Rational uu = M.m11 * ux * ux + 2 * M.m12 * ux * uy + M.m22 * uy * uy, vv = M.m11 * vx * vx + 2 * M.m12 * vx * vy + M.m22 * vy * vy;
  if (k >= 0) return uv <= 0 || uv * uv <= k * k * uu * vv;
  return uv < 0 && uv * uv >= k * k * uu * vv;
}

}  // namespace

RC_GTEST_PROP(LS_T11, RunsEndAndKeepEveryTwoSitesMuApart, ()) {
  refiners::ls::LsParameters p;
  p.theta_bound = *rc::gen::elementOf(std::vector<double>{1, 5, 10, 15, 20, 20.5});
  p.size = 0;
  p.max_vertices = 20000, p.max_seconds = 1e9;  // no time budget: the vertex budget ends every run
  // A comb (narrow slots, right angles) in a diagonal metric, which keeps its corners right, or a
  // random polygon in any metric.
  const int kind = *rc::gen::inRange(0, 3);
  const auto corners = kind == 0 ? gen::random_comb() : gen::random_domain(kind == 2, true);
  const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101);
  const double angle = kind == 0 ? 0 : *rc::gen::inRange(0, 180) * M_PI / 180;
  const double c = std::cos(angle), s = std::sin(angle);
  const predicates::Sym2<double> Md{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c};
  const predicates::Sym2<Rational> M{Rational(Md.m11), Rational(Md.m12), Rational(Md.m22)};
  const Interval gamma = theory::ls_t11_gamma(rational_from_double(p.theta_bound), 256);
  const Rational gamma_hi = rational_from_double(gamma.upper_double());
  // Theorem 11's separation at every corner, from above: cos(angle) <= 1 − γ_hi⁴/2 <= cos 2 arcsin(γ²/2).
  const std::size_t n = corners.size();
  std::vector<predicates::Point2<Rational>> q;
  for (const auto& v : corners) q.push_back({Rational(v.x), Rational(v.y)});
  for (std::size_t k = 0; k < n; ++k) {
    const auto &before = q[(k + n - 1) % n], &at = q[k], &after = q[(k + 1) % n];
    RC_PRE(cos_at_most(M, before.x - at.x, before.y - at.y, after.x - at.x, after.y - at.y, 1 - gamma_hi * gamma_hi * gamma_hi * gamma_hi / 2));
  }
  RC_TAG(kind == 0 ? "comb" : kind == 2 ? "non-convex" : "convex", "theta_bound " + std::to_string(static_cast<int>(p.theta_bound)));
  const auto r = refiners::ls::refine_ls(refiners::common::Domain(corners), fields::make_field("constant", {{"m11", Md.m11}, {"m12", Md.m12}, {"m22", Md.m22}}), p);
  RC_LOG() << r.stop_reason;
  RC_ASSERT(r.consistent);

  const std::optional<Rational> delta2 = nonadjacent_edges_distance2(M, q);
  RC_PRE(delta2.has_value());  // a triangle: every pair intertwined, no bound
  const Rational mu2 = *delta2 / (4 * gamma_hi * gamma_hi);
  const double mu2d = mu2.convert_to<double>();
  const auto& sites = r.mesh.sites;
  std::size_t pairs_checked_exactly = 0;
  double least2 = std::numeric_limits<double>::infinity();
  for (std::size_t u = 0; u < sites.size(); ++u)
    for (std::size_t v = u + 1; v < sites.size(); ++v) {
      const double dx = sites[u].x - sites[v].x, dy = sites[u].y - sites[v].y;
      const double dist2 = Md.m11 * dx * dx + 2 * Md.m12 * dx * dy + Md.m22 * dy * dy;
      least2 = std::min(least2, dist2);
      if (dist2 > 1.01 * mu2d + 1e-300) continue;  // far apart
      ++pairs_checked_exactly;
      RC_ASSERT(d2(M, {Rational(sites[u].x), Rational(sites[u].y)}, {Rational(sites[v].x), Rational(sites[v].y)}) >= mu2);
    }
  RC_CLASSIFY(pairs_checked_exactly > 0, "pairs near mu checked exactly");
  const double ratio = std::sqrt(least2 / mu2d);  // how much room the bound leaves
  RC_TAG(ratio < 1.5 ? "closest pair under 1.5 mu" : ratio < 2 ? "closest pair 1.5 to 2 mu" : "closest pair 2 mu or more");
  RC_TAG(sites.size() < 20 ? "under 20 sites" : sites.size() < 500 ? "20 to 499 sites" : "500 sites or more");
}

// LS Lemmas 17, 21 and 23 on the traces of the runs above (constant fields: bdr = ∞, τ ≡ 1 ≤ γ,
// size rule off, Theorem 11's conditions decided in the test). With m the least distance between
// two sites before an insertion and w any earlier site:
//   rule 1, a split of an encroached subsegment (Lemma 17): d(z, w) ≥ min{m, lfs_min/γ}; the
//     lemma's m (the encroacher's distance to an endpoint) is at least this m;
//   rule 2, a split because a violator would encroach (Lemma 23): d(z, w) ≥ m;
//   rule 3, a site at a poor-angle Voronoi vertex (Lemma 21): d(q, w) ≥ γ√(γ²+1)·m, at the exact
//     vertex q; the site is q rounded to doubles, so the assertion allows √λ_max times the
//     rounding (2 ulps per coordinate).
// Lemma 21's γ√(γ²+1) is taken at γ's lower end and lfs_min/γ at its upper one (both weaker).
// Rules 1 and 2 are compared exactly (squared, in rationals); rule 3 in long double with a
// relative allowance of 10⁻¹² besides the rounding's.
RC_GTEST_PROP(LS_L17_L21_L23, EveryInsertionKeepsItsLemmasDistance, ()) {
  refiners::ls::LsParameters p;
  p.theta_bound = *rc::gen::elementOf(std::vector<double>{1, 5, 10, 15, 20, 20.5});
  p.size = 0;
  p.max_vertices = 20000, p.max_seconds = 1e9;  // no time budget: the vertex budget ends every run
  const auto corners = gen::random_comb();
  const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101);
  const predicates::Sym2<double> Md{l1, 0, l2};  // diagonal: the comb's corners stay right
  const predicates::Sym2<Rational> M{Rational(Md.m11), Rational(Md.m12), Rational(Md.m22)};
  const Interval gamma = theory::ls_t11_gamma(rational_from_double(p.theta_bound), 256);
  const long double g_lo = gamma.lower_double(), g_hi = gamma.upper_double();
  const auto r = refiners::ls::refine_ls(refiners::common::Domain(corners), fields::make_field("constant", {{"m11", l1}, {"m12", 0.0}, {"m22", l2}}), p);
  RC_ASSERT(r.consistent);
  // lfs_min ≥ δ/2 (as in LS_T11), δ² exact.
  std::vector<predicates::Point2<Rational>> q;
  for (const auto& v : corners) q.push_back({Rational(v.x), Rational(v.y)});
  const std::optional<Rational> delta2 = nonadjacent_edges_distance2(M, q);
  const auto dist = [&](const predicates::Point2<double>& u, const predicates::Point2<double>& v) {
    const long double dx = static_cast<long double>(u.x) - v.x, dy = static_cast<long double>(u.y) - v.y;
    return std::sqrt(l1 * dx * dx + l2 * dy * dy);
  };
  const auto& sites = r.mesh.sites;
  const std::size_t first = sites.size() - r.trace.size();  // the corners come first, untraced
  long double m = INFINITY;
  for (std::size_t u = 0; u < first; ++u)
    for (std::size_t v = u + 1; v < first; ++v) m = std::min(m, dist(sites[u], sites[v]));
  const long double lmax = std::max(l1, l2);
  const auto exact2 = [&](const predicates::Point2<double>& u, const predicates::Point2<double>& v) {
    return d2(M, {Rational(u.x), Rational(u.y)}, {Rational(v.x), Rational(v.y)});
  };
  std::optional<Rational> m2;  // m², exactly
  for (std::size_t u = 0; u < first; ++u)
    for (std::size_t v = u + 1; v < first; ++v)
      if (const Rational x = exact2(sites[u], sites[v]); !m2 || x < *m2) m2 = x;
  const std::optional<Rational> lfs_over_gamma2 = delta2 ? std::optional<Rational>(*delta2 / (4 * Rational(g_hi) * Rational(g_hi))) : std::nullopt;
  std::array<int, 4> checked{};
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    const auto& t = r.trace[k];
    const predicates::Point2<double> z{t.x, t.y};
    std::optional<Rational> nearest2;
    long double nearest = INFINITY;
    for (std::size_t w = 0; w < first + k; ++w) {
      nearest = std::min(nearest, dist(z, sites[w]));
      if (const Rational x = exact2(z, sites[w]); !nearest2 || x < *nearest2) nearest2 = x;
    }
    if (t.rule == 1) RC_ASSERT(*nearest2 >= (lfs_over_gamma2 ? std::min(*m2, *lfs_over_gamma2) : *m2));  // Lemma 17
    if (t.rule == 2) RC_ASSERT(*nearest2 >= *m2);                                                       // Lemma 23
    if (t.rule == 3) {                                                                                   // Lemma 21
      const long double ulp = std::ldexp(1.0L, std::ilogb(std::max(std::abs(t.x), std::abs(t.y))) - 52);
      const long double bound = g_lo * std::sqrt(g_lo * g_lo + 1) * m - std::sqrt(lmax) * 2 * ulp * std::sqrt(2.0L);
      RC_ASSERT(nearest >= bound * (1 - 1e-12L));
    }
    ++checked[t.rule];
    m = std::min(m, nearest);
    m2 = std::min(*m2, *nearest2);
  }
  RC_CLASSIFY(checked[1] > 0, "rule 1 checked");
  RC_CLASSIFY(checked[2] > 0, "rule 2 checked");
  RC_CLASSIFY(checked[3] > 0, "rule 3 checked");
}

// The filters (FilterInterval boxes of Voronoi vertices for containment in Ω and the size rule,
// the diametral-ellipse test that discards sites before the cells along a subsegment are
// computed) only speed the refiner up: with them off, every decision in rationals, a run makes
// the same insertions and ends with the same mesh, double for double.
RC_GTEST_PROP(LS_Filters, FilteredRunIsTheExactRun, ()) {
  const bool reflex = *rc::gen::arbitrary<bool>();
  const auto corners = *rc::gen::arbitrary<bool>() ? gen::random_comb() : gen::random_domain(reflex, false);
  const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101), angle = *rc::gen::inRange(0, 180) * M_PI / 180;
  const double c = std::cos(angle), s = std::sin(angle);
  const auto field = fields::make_field("constant", {{"m11", l1 * c * c + l2 * s * s}, {"m12", (l1 - l2) * c * s}, {"m22", l1 * s * s + l2 * c * c}});
  refiners::ls::LsParameters p;
  p.theta_bound = *rc::gen::elementOf(std::vector<double>{5, 15, 20, 25});
  p.size = *rc::gen::elementOf(std::vector<double>{0, 0.5, 1, 2});
  p.max_vertices = 300, p.max_seconds = 1e9;
  const refiners::common::Domain domain(corners);
  const auto filtered = refiners::ls::refine_ls(domain, field, p);
  p.filters = false;
  const auto exact = refiners::ls::refine_ls(domain, field, p);
  RC_TAG(filtered.mesh.sites.size() < 50 ? "under 50 sites" : "50 sites or more");
  gen::assert_same_run(filtered, exact);
}

RC_GTEST_PROP(LS_S9, FinishedRunsAreTheDualOfTheExactDiagram, ()) {
  const Run run = random_run();
  const auto& r = run.r;
  const std::size_t n = r.mesh.sites.size();
  RC_TAG(run.domain, run.separation, r.consistent ? "finished" : "stopped", n < 50 ? "under 50 sites" : n < 200 ? "50 to 199 sites" : "200 sites or more");
  if (!r.consistent) {
    // A stop names the vertex budget, or, where Theorem 11's conditions fail (refinement near
    // acute corners or above 20.7° need not end), splits below 2⁻³⁰ of an edge or the resolution
    // of doubles.
    RC_LOG() << run.separation << ": " << r.stop_reason;
    RC_ASSERT(r.stop_reason.find("budget") != std::string::npos ||
              (run.separation != "separation holds" && (r.stop_reason.find("no double point") != std::string::npos ||
                                                        r.stop_reason.find("below 2⁻³⁰ of its length") != std::string::npos)));
    return;
  }
  const auto certified = gen::assert_dual_of_exact_diagram(r.mesh);
  if (!certified) return;
  const geometry::Mesh<Rational>& m = certified->mesh;

  const auto& M = m.metrics[0];
  const Rational s2 = sin2_above(run.p.theta_bound), size2 = rational_from_double(run.p.size) * rational_from_double(run.p.size);
  const Rational det = M.m11 * M.m22 - M.m12 * M.m12;
  std::set<std::pair<int, int>> edges;
  for (const auto& t : r.mesh.triangles) {
    const auto &a = m.sites[t[0]], &b = m.sites[t[1]], &c = m.sites[t[2]];
    for (int i = 0; i < 3; ++i) {
      RC_ASSERT(predicates::angle_at_least_arcsin(m.sites[t[(i + 2) % 3]], m.sites[t[i]], m.sites[t[(i + 1) % 3]], M, s2));
      edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
    }
    if (run.p.size > 0) {
      // Circumradius in M, R = ℓ_ab ℓ_bc ℓ_ca / (4 K_M), K_M = √det M · |orient| / 2:
      // R² <= size² ⇔ ℓ_ab² ℓ_bc² ℓ_ca² <= 4 size² det M orient².
      const Rational orient = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      RC_ASSERT(d2(M, a, b) * d2(M, b, c) * d2(M, c, a) <= 4 * size2 * det * orient * orient);
    }
  }
  for (const auto& [u, v] : r.mesh.segments) RC_ASSERT(edges.count(std::minmax(u, v)) == 1u);
}
