// The Labelle–Shewchuk refiner (refiners/ls/) certified by the exact oracle on every finished run
// (issue 16), and LS Theorem 11 and Lemmas 17, 21 and 23 checked on its traces.
//
// LS.T11 (the T part): with θ_bound < arcsin(1/(2√2)), no size rule and every pair of adjoining
// segments at least 2 arcsin(γ²/2) apart in the metric of their common corner (decided here
// exactly), the run finishes, the oracle certifies it (as in LS.S9 below), every angle is at least
// θ_bound in the metrics of its triangle's vertices, and every two sites have d_u(v) ≥ μ =
// min{lfs_min/γ, bdr_min(γ)/((γ⁵+γ³)√(γ²+1))}. The fields are those whose bdr and lfs are known: one metric (the
// constant field, which the refiner meshes on Del_M), or two metrics M_in on a disc and M_out off it
// with τ(M_in, M_out) ≤ γ decided exactly (the refiner's path for sites with different metrics, the
// true diagram). Every two points of Ω then have τ ≤ γ, so bdr = ∞ everywhere (LS Definition 4),
// μ = lfs_min/γ, and every two adjacent edges of Ω are intertwined (Definition 5: τ(q, b) ≤ γ for
// every q): non-intertwined feature points lie on non-adjacent edges, and a disc centred at p
// touching both has a diameter of at least their M_p-distance. So lfs_min ≥ δ/2, δ the least
// M-distance between two non-adjacent edges over the field's metrics M (a rational; the assertion
// d² ≥ δ²/(4γ_hi²) is the theorem's, weakened only by γ's enclosure and this bound). A two-valued
// field with τ(M_in, M_out) > γ has bdr_min = 0 (points on either side of the disc's rim), where
// the theorem promises nothing. One smooth field, the linear one, has closed-form lower bounds on
// bdr_min and lfs_min (LinearFieldRunsKeepEveryTwoSitesMuApart below); others have none here yet.
//
// LS.S9: a finished run (no encroached subsegment, no violator) is the dual of the exact diagram:
// the oracle's D|Ω of the final sites has no orphans, every arc and vertex wedged, Theorem 7's
// preconditions, a dual that is a triangulation of Ω and equals the mesh triangle for triangle;
// every angle is at least θ_bound and every circumradius at most `size` in the metric, decided
// exactly by closed forms here (not by the refiner's code); every segment of the PSLG (edges of Ω,
// interior segments) is a union of mesh edges (decided from the domain).
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "geometry/polygon.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "predicates/angle.hpp"
#include "property_tests/generators/domains.hpp"
#include "property_tests/generators/metrics.hpp"
#include "property_tests/ls_same_run.hpp"
#include "property_tests/oracle_certified.hpp"
#include "property_tests/small_angle_exemption.hpp"
#include "property_tests/theta_bound.hpp"
#include "property_tests/pslg_domain.hpp"
#include "property_tests/tau_bounded_field.hpp"
#include "refiners/ls/ls_refiner.hpp"
#include "refiners/ls/theorem11_conditions.hpp"
#include "theory/ls_theorem11.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

using namespace anisocert;

namespace {

// θ_bound's band of five degrees, for the tags ("theta_bound 15° to 20°").
std::string theta_bucket(double theta) {
  const int from = static_cast<int>(theta / 5) * 5;
  return "theta_bound " + std::to_string(from) + "° to " + std::to_string(from + 5) + "°";
}

struct Run {
  refiners::ls::LsParameters p;
  refiners::ls::LsResult r;
  predicates::Sym2<double> M;
  std::optional<refiners::common::Domain> X;  // Ω with the rest of the PSLG
  std::string domain, separation;
};

// A random constant metric (eigenvalues 1 to 100, or with a ratio up to 10², any orientation; a
// diagonal one on combs), a random domain (convex or not, with or without acute corners, with or
// without interior points and segments; or a comb with narrow slots), θ_bound from 5° to 30° (above 20.7° Theorem 11 gives no guarantee) and a size
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
  run.p.theta_bound = *gen::theta_in_tenths(50, 300);  // 5° to 30°: Theorem 11's range and beyond
  run.p.size = *rc::gen::elementOf(std::vector<double>{0, 0, 0.5, 1, 2});
  run.p.max_vertices = 400, run.p.max_seconds = 1e9;
  run.X.emplace(kind == 4 ? refiners::common::Domain(corners) : gen::domain_with_interior(corners));
  const refiners::common::Domain& domain = *run.X;
  const auto field = fields::make_field("constant", {{"m11", run.M.m11}, {"m12", run.M.m12}, {"m22", run.M.m22}});
  run.r = refiners::ls::refine_ls(domain, field, run.p);
  const auto t11 = refiners::ls::theorem11_conditions(domain, std::vector(domain.vertices().size(), run.M), run.p.theta_bound);
  run.separation = !t11.theta_admissible             ? "theta_bound above Theorem 11's"
                   : t11.corners_failing.empty() ? "separation holds"
                                                 : "separation fails";
  return run;
}

using gen::d2;
using gen::cos_at_most;
using gen::exact;
using gen::nonadjacent_edges_distance2;
using gen::tau_bounded_field;
using gen::TauBoundedField;
using gen::turned;

// The squared distance from a to b in M, in double and long double (to sort out the pairs to
// decide exactly).
double approx_d2(const predicates::Sym2<double>& M, const predicates::Point2<double>& a, const predicates::Point2<double>& b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return M.m11 * dx * dx + 2 * M.m12 * dx * dy + M.m22 * dy * dy;
}
long double approx_d2l(const predicates::Sym2<double>& M, const predicates::Point2<double>& a, const predicates::Point2<double>& b) {
  const long double dx = static_cast<long double>(a.x) - b.x, dy = static_cast<long double>(a.y) - b.y;
  return M.m11 * dx * dx + 2 * M.m12 * dx * dy + M.m22 * dy * dy;
}

// λ_max(M) from above: the trace bounds it.
long double largest_eigenvalue_above(const predicates::Sym2<double>& M) {
  return (static_cast<long double>(M.m11) + M.m22) * (1 + 1e-15L);
}

// min{d_u(v)², d_v(u)²} in the sites' metrics, exactly.
Rational d2_between(const refiners::ls::LsResult& r, std::size_t u, std::size_t v) {
  const auto& s = r.mesh.sites;
  const predicates::Point2<Rational> a{Rational(s[u].x), Rational(s[u].y)}, b{Rational(s[v].x), Rational(s[v].y)};
  return std::min(d2(exact(r.mesh.metrics[u]), a, b), d2(exact(r.mesh.metrics[v]), a, b));
}

// A run under Theorem 11's conditions: θ_bound below 20.7°, no size rule, a comb (narrow slots,
// right angles) or a random polygon, convex or not, a τ-bounded field, and the separation at every
// corner in the corner's metric, cos(angle) ≤ 1 − γ_hi⁴/2 ≤ cos 2 arcsin(γ²/2), decided exactly.
// The vertex budget alone ends a run (no time budget).
struct Theorem11Run {
  refiners::ls::LsParameters p;
  double gamma_lo = 0, gamma_hi = 0;  // γ's enclosure, ends rounded outward
  TauBoundedField field;
  Rational delta2;  // δ², the least over the field's metrics
  refiners::ls::LsResult r;
};

Theorem11Run theorem11_run() {
  Theorem11Run run;
  run.p.theta_bound = *gen::theta_in_tenths(10, 205);  // 1° to 20.5°
  run.p.size = 0;
  run.p.max_vertices = 20000, run.p.max_seconds = 1e9;
  const int kind = *rc::gen::inRange(0, 3);
  const auto corners = kind == 0 ? gen::random_comb() : gen::random_domain(kind == 2, true);
  const Interval gamma = theory::ls_t11_gamma(rational_from_double(run.p.theta_bound), 256);
  run.gamma_lo = gamma.lower_double(), run.gamma_hi = gamma.upper_double();
  run.field = tau_bounded_field(corners, kind == 0, Rational(run.gamma_lo) * Rational(run.gamma_lo));
  const std::size_t n = corners.size();
  std::vector<predicates::Point2<Rational>> q;
  for (const auto& v : corners) q.push_back({Rational(v.x), Rational(v.y)});
  const Rational g_hi(run.gamma_hi), g4 = g_hi * g_hi * g_hi * g_hi;
  for (std::size_t k = 0; k < n; ++k) {
    const auto &before = q[(k + n - 1) % n], &at = q[k], &after = q[(k + 1) % n];
    const auto M = exact(run.field.field.at(corners[k].x, corners[k].y));
    RC_PRE(cos_at_most(M, before.x - at.x, before.y - at.y, after.x - at.x, after.y - at.y, 1 - g4 / 2));
  }
  std::optional<Rational> delta2;
  for (const auto& M : run.field.metrics)
    if (const auto d = nonadjacent_edges_distance2(exact(M), q); d && (!delta2 || *d < *delta2)) delta2 = d;
  RC_PRE(delta2.has_value());  // a triangle: every pair intertwined, no bound
  run.delta2 = *delta2;
  RC_TAG(kind == 0 ? "comb" : kind == 2 ? "non-convex" : "convex", run.field.kind,
         theta_bucket(run.p.theta_bound));
  run.r = refiners::ls::refine_ls(refiners::common::Domain(corners), run.field.field, run.p);
  for (const auto& M : run.r.mesh.metrics)  // the test's field, as the refiner evaluated it
    RC_ASSERT(std::find(run.field.metrics.begin(), run.field.metrics.end(), M) != run.field.metrics.end());
  return run;
}


// Theorem 11's conclusions on a run: it finished; the oracle certifies it (as in LS_S9), with every
// angle at least θ_bound in the metrics of each triangle's vertices, points of t (the refiner also
// judges at the dual vertex); every two sites have d_u(v)² ≥ μ² and d_v(u)² ≥ μ², exactly.
void assert_theorem11(const refiners::ls::LsResult& r, double theta_bound, const Rational& mu2) {
  RC_LOG() << r.stop_reason;
  RC_ASSERT(r.consistent);
  if (const auto certified = gen::assert_dual_of_exact_diagram(r.mesh)) {
    const Rational s2 = gen::sin2_above(theta_bound);
    const auto& m = certified->mesh;
    for (const auto& t : r.mesh.triangles)
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
          RC_ASSERT(predicates::angle_at_least_arcsin(m.sites[t[(i + 2) % 3]], m.sites[t[i]], m.sites[t[(i + 1) % 3]], m.metrics[t[k]], s2));
  }
  const double mu2d = mu2.convert_to<double>();
  const auto& sites = r.mesh.sites;
  std::size_t pairs_checked_exactly = 0;
  double least2 = std::numeric_limits<double>::infinity();
  for (std::size_t u = 0; u < sites.size(); ++u)
    for (std::size_t v = u + 1; v < sites.size(); ++v) {
      const double dist2 = std::min(approx_d2(r.mesh.metrics[u], sites[u], sites[v]), approx_d2(r.mesh.metrics[v], sites[u], sites[v]));
      least2 = std::min(least2, dist2);
      if (dist2 > 1.01 * mu2d + 1e-300) continue;  // far apart
      ++pairs_checked_exactly;
      RC_ASSERT(d2_between(r, u, v) >= mu2);  // d_u(v) and d_v(u)
    }
  RC_CLASSIFY(pairs_checked_exactly > 0, "pairs near mu checked exactly");
  const double ratio = std::sqrt(least2 / mu2d);  // how much room the bound leaves
  RC_TAG(ratio < 1.5 ? "closest pair under 1.5 mu" : ratio < 2 ? "closest pair 1.5 to 2 mu" : ratio < 10 ? "closest pair 2 to 10 mu" : "closest pair 10 mu or more");
  RC_TAG(sites.size() < 20 ? "under 20 sites" : sites.size() < 500 ? "20 to 499 sites" : "500 sites or more");
}

}  // namespace

// LS.T11's corner report (refiners/ls/theorem11_conditions, behind the report's "holds at every
// corner" or "fails at corners …" and the stop messages' corner notes) against an independent
// computation in long double: γ(θ_bound) by bisection on γ⁸ + 2γ⁴√(γ²+1) sin θ − γ⁴ − 1 (LS
// Theorem 11), the required separation 2 arcsin(γ²/2), and the angle between every two segments
// that meet at a vertex of X, in the metric there, by its arccosine. A vertex with an angle within
// 10⁻⁹° of the separation is not judged here. Random polygons, convex or not, with interior points
// and segments, a random metric at every vertex, θ_bound from 1° to 20.6° in tenths.
RC_GTEST_PROP(LS_T11, CornerReportAgreesWithAnglesInLongDouble, ()) {
  using L = long double;
  const auto corners = gen::random_domain(*rc::gen::arbitrary<bool>(), *rc::gen::arbitrary<bool>());
  const refiners::common::Domain domain = gen::domain_with_interior(corners);
  const double theta = *gen::theta_in_tenths(10, 206);
  const auto& X = domain.vertices();
  std::vector<predicates::Sym2<double>> metrics;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101), a = *rc::gen::inRange(0, 180) * M_PI / 180;
    const double c = std::cos(a), s = std::sin(a);
    metrics.push_back({l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c});
  }
  const auto t11 = refiners::ls::theorem11_conditions(domain, metrics, theta);
  RC_ASSERT(t11.theta_admissible);
  const L sin_theta = std::sin(static_cast<L>(theta) * std::acos(L(-1)) / 180);
  L lo = 1, hi = 2;  // the polynomial is negative at 1 (sin θ < 1/(2√2)) and positive at 2
  for (int i = 0; i < 200; ++i) {
    const L g = (lo + hi) / 2, g4 = g * g * g * g;
    (g4 * g4 + 2 * g4 * std::sqrt(g * g + 1) * sin_theta - g4 - 1 < 0 ? lo : hi) = g;
  }
  RC_ASSERT(lo >= static_cast<L>(t11.gamma_lo) - 1e-15L && lo <= static_cast<L>(t11.gamma_hi) + 1e-15L);
  const L degrees = 180 / std::acos(L(-1)), separation = 2 * std::asin(lo * lo / 2) * degrees;
  RC_ASSERT(separation >= static_cast<L>(t11.separation_lo) - 1e-9L && separation <= static_cast<L>(t11.separation_hi) + 1e-9L);
  std::vector<std::vector<std::size_t>> ends(X.size());  // the far ends of the segments at each vertex
  for (std::size_t e = 0; e < domain.segment_count(); ++e) {
    const auto [a, b] = domain.segment_ends(e);
    ends[static_cast<std::size_t>(a)].push_back(static_cast<std::size_t>(b));
    ends[static_cast<std::size_t>(b)].push_back(static_cast<std::size_t>(a));
  }
  const auto failing = [&](std::size_t k) { return std::find(t11.corners_failing.begin(), t11.corners_failing.end(), static_cast<int>(k)) != t11.corners_failing.end(); };
  const auto undecided = [&](std::size_t k) { return std::find(t11.corners_undecided.begin(), t11.corners_undecided.end(), static_cast<int>(k)) != t11.corners_undecided.end(); };
  int judged_failing = 0;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const auto& M = metrics[k];
    const auto inner = [&](std::size_t u, std::size_t w) {
      const L ux = X[u].x - X[k].x, uy = X[u].y - X[k].y, wx = X[w].x - X[k].x, wy = X[w].y - X[k].y;
      return ux * (M.m11 * wx + M.m12 * wy) + uy * (M.m12 * wx + M.m22 * wy);
    };
    L least = 180;
    for (std::size_t i = 0; i < ends[k].size(); ++i)
      for (std::size_t j = i + 1; j < ends[k].size(); ++j) {
        const std::size_t u = ends[k][i], w = ends[k][j];
        least = std::min(least, std::acos(inner(u, w) / std::sqrt(inner(u, u) * inner(w, w))) * degrees);
      }
    if (least < separation - 1e-9L) {
      RC_ASSERT(failing(k));
      ++judged_failing;
    } else if (least > separation + 1e-9L) {
      RC_ASSERT(!failing(k) && !undecided(k));
    }
  }
  RC_TAG(judged_failing == 0 ? "separation holds at every vertex" : "separation fails somewhere");
}

RC_GTEST_PROP(LS_T11, RunsEndAndKeepEveryTwoSitesMuApart, ()) {
  const Theorem11Run run = theorem11_run();
  assert_theorem11(run.r, run.p.theta_bound, run.delta2 / (4 * Rational(run.gamma_hi) * Rational(run.gamma_hi)));
}

namespace {

// The linear field (fields/linear.cpp) with dyadic hx and h0, so that k = 2(hx − h0) is exact as
// the field computes it, and the bounds on it that the properties below use (the argument is in
// the comment of LS_T11.LinearFieldRunsKeepEveryTwoSitesMuApart).
struct LinearField {
  double hx, h0;
  Rational k;
  fields::MetricField field;
  // ρ = 1 + 2⁻⁴⁷ covers the field's rounding: τ(p, q) ≤ ρ·max(h_p/h_q, h_q/h_p), d_p(q) ≥ |y_q − y_p|/(ρ h_p).
  static Rational rho() { return 1 + Rational(std::ldexp(1.0, -47)); }
  // h(y) = h0 + k|y − ½|, exactly.
  Rational h(const Rational& y) const { return Rational(h0) + k * abs(y - Rational(1, 2)); }
  // bdr_min(γ) ≥ (1 − ρ/γ)/(kρ), for γ > ρ.
  Rational bdr_min_below(const Rational& gamma) const { return (1 - rho() / gamma) / (k * rho()); }
};

LinearField linear_field() {
  const double hx = *rc::gen::elementOf(std::vector<double>{0.125, 0.25, 0.5}), h0 = hx / *rc::gen::elementOf(std::vector<double>{2, 4, 8});
  LinearField f{hx, h0, 2 * (Rational(hx) - Rational(h0)), fields::make_field("linear", {{"hx", hx}, {"h0", h0}})};
  RC_ASSERT(Rational(2 * (hx - h0)) == f.k);
  return f;
}

}  // namespace

// LS.T11 on a smooth field whose bdr_min and lfs_min have certified bounds in closed form: the
// linear field (fields/linear.cpp) M(x, y) = diag(1/hx², 1/h̃(y)²), h̃ the double of
// h(y) = h0 + k|y − ½|, k = 2(hx − h0), with hx and h0 dyadic so that k is exact. No size rule,
// θ_bound below 20.7°, Theorem 11's separation at every corner in its metric (decided exactly), as
// in the runs above, on random polygons (convex or not) around the origin.
//   Rounding. h̃ = h(1 + e), |e| < 4u (u = 2⁻⁵³: a subtraction, a product, a sum of non-negative
//   terms), and m22 = 1/h̃² rounded twice, so m22 = (1 + ε)/h², |ε| < 2⁻⁴⁹; m11 is one double for
//   every point. With ρ = 1 + 2⁻⁴⁷: τ(p, q) ≤ ρ·max(h_p/h_q, h_q/h_p) (both metrics diagonal, equal
//   m11), and d_p(q) ≥ |y_q − y_p|/(ρ h_p).
//   bdr_min (LS Definition 4). If τ(p, q) > γ, h_q/h_p or h_p/h_q exceeds γ′ = γ/ρ; h is
//   k-Lipschitz, so k|y_q − y_p| ≥ |h_q − h_p| > (1 − 1/γ′)h_p in either case, and d_p(q) >
//   (1 − 1/γ′)/(kρ). So bdr_min(γ) ≥ β = (1 − ρ/γ)/(kρ) (γ at its lower end: bdr grows with γ).
//   lfs_min (LS Definition 5). A disc centred at p that meets feature points q, q′ has radius at
//   least d_p(q, q′)/2 ≥ √λ |q − q′|/2, λ = min(m11, 1/(ρ h_max²)) below M_p's eigenvalues (h_max:
//   h's greatest value over Ω's y range). Points not intertwined lie on non-adjacent edges
//   (|q − q′| ≥ δ_E, the least Euclidean distance between them), or on two edges at a corner b with
//   τ(q, b) > γ (or q′): then |h_q − h_b| > (1 − 1/γ′)h_b, so |q − b| ≥ |y_q − y_b| > η_b =
//   (1 − 1/γ′)h_b/k, and q′ on the other edge is at least η_b·min(1, sin φ_b) from q, φ_b the
//   corner's angle between its edges. So lfs_min² ≥ (λ/4)·min(δ_E², min_b η_b² min(1, sin²φ_b)).
//   μ² = min{lfs_min²/γ², β²/((γ⁵ + γ³)²(γ² + 1))}, γ at its upper end outside β.
// Both bounds are far below the refiner's spacing (the tags say how far): the property fails only
// for sites much closer than LS's analysis allows, such as a split or a rounding that lands on a
// site's neighbour.
RC_GTEST_PROP(LS_T11, LinearFieldRunsKeepEveryTwoSitesMuApart, ()) {
  refiners::ls::LsParameters p;
  p.theta_bound = *gen::theta_in_tenths(10, 200);  // 1° to 20°
  p.size = 0;
  p.max_vertices = 20000, p.max_seconds = 1e9;
  const LinearField f = linear_field();
  const bool reflex = *rc::gen::arbitrary<bool>();
  const auto corners = gen::random_domain(reflex, true);
  const Interval gamma = theory::ls_t11_gamma(rational_from_double(p.theta_bound), 256);
  const Rational g_lo(gamma.lower_double()), g_hi(gamma.upper_double()), rho = LinearField::rho();
  RC_ASSERT(g_lo > rho);
  const std::size_t n = corners.size();
  std::vector<predicates::Point2<Rational>> q;
  for (const auto& v : corners) q.push_back({Rational(v.x), Rational(v.y)});
  const Rational rate = (1 - rho / g_lo) / f.k;  // η_b / h_b
  Rational h_max(0), corner_least;              // h's greatest value over Ω; min_b η_b² min(1, sin²φ_b)
  bool first = true;
  for (std::size_t i = 0; i < n; ++i) {
    const auto &before = q[(i + n - 1) % n], &at = q[i], &after = q[(i + 1) % n];
    RC_PRE(cos_at_most(exact(f.field.at(corners[i].x, corners[i].y)), before.x - at.x, before.y - at.y, after.x - at.x, after.y - at.y,
                       1 - g_hi * g_hi * g_hi * g_hi / 2));
    h_max = std::max(h_max, f.h(at.y));
    const Rational ux = before.x - at.x, uy = before.y - at.y, vx = after.x - at.x, vy = after.y - at.y, cross = ux * vy - uy * vx;
    const Rational sin2 = ux * vx + uy * vy > 0 ? cross * cross / ((ux * ux + uy * uy) * (vx * vx + vy * vy)) : Rational(1);
    const Rational eta = rate * f.h(at.y);
    if (first || eta * eta * sin2 < corner_least) corner_least = eta * eta * sin2;
    first = false;
  }
  const Rational lambda = std::min(Rational(f.field.at(0, 0).m11), 1 / (rho * h_max * h_max));
  const Rational beta = f.bdr_min_below(g_lo);
  const Rational delta_e2 = *nonadjacent_edges_distance2({1, 0, 1}, q);
  const Rational lfs2 = lambda / 4 * std::min(delta_e2, corner_least);
  const Rational g2 = g_hi * g_hi, g3 = g2 * g_hi, g5 = g3 * g2;
  const Rational mu2 = std::min(lfs2 / g2, beta * beta / ((g5 + g3) * (g5 + g3) * (g2 + 1)));
  RC_TAG(reflex ? "non-convex" : "convex", theta_bucket(p.theta_bound),
         lfs2 / g2 < beta * beta / ((g5 + g3) * (g5 + g3) * (g2 + 1)) ? "mu from lfs_min" : "mu from bdr_min");
  assert_theorem11(refiners::ls::refine_ls(refiners::common::Domain(corners), f.field, p), p.theta_bound, mu2);
}

// LS Lemmas 17, 21 and 23 on the traces of the runs above (bdr = ∞, every τ ≤ γ, size rule off,
// Theorem 11's conditions decided in the test). With d(u, v) = min{d_u(v), d_v(u)} (LS §3), m the
// least d between two sites before an insertion and w any earlier site:
//   rule 1, a split of an encroached subsegment (Lemma 17): d(z, w) ≥ min{m, lfs_min/γ}; the
//     lemma's m (the encroacher's distance to an endpoint) is at least this m;
//   rule 2, a split because a violator (rule 3 or 7) would encroach (Lemma 23): d(z, w) ≥ m;
//   rules 3 and 7, a site at a poor-angle or unwedged Voronoi vertex q (Lemma 21, by Lemmas 18
//     and 19): d(q, w) ≥ γ√(γ²+1)·m. The site q̃ is q rounded, within the trace's displacement e
//     of q, so d_w(q̃) ≥ γ²√(γ²+1)m − √λ_max e, and d_q̃(w) ≥ d_w(q̃)/γ (τ ≤ γ): the assertion
//     allows √λ_max e. And Lemma 18's premise, that q is a Voronoi vertex: with r̃ the
//     circumradius the trace records (one triangle site's distance at q̃), every earlier w has
//     d_w(q̃) ≥ r̃ − 2√λ_max e, and at least three have d_w(q̃) ≤ r̃ + 2√λ_max e.
// Rule 5 (inverted) is LS §9's, but Lemma 21's and 23's proofs cover violators of poor angle
// (Lemma 18), wedge violators (19) and violators by mistaken identity (20) only; rules 6 and 8
// (island, tie) are this refiner's, not LS §9's. Their sites and the splits made for them are
// counted (tagged), not checked; Theorem 11's μ above covers them too.
// Lemma 21's γ√(γ²+1) is taken at γ's lower end and lfs_min/γ at its upper one (both weaker).
// Rules 1 and 2 are compared exactly (squared, in rationals); rules 3 and 7 in long double with a
// relative allowance of 10⁻¹² besides the rounding's.
RC_GTEST_PROP(LS_L17_L21_L23, EveryInsertionKeepsItsLemmasDistance, ()) {
  const Theorem11Run run = theorem11_run();
  const auto& r = run.r;
  RC_LOG() << r.stop_reason << "\n";
  RC_ASSERT(r.consistent);
  const long double g_lo = run.gamma_lo;
  long double lmax = 0;  // √λ_max bounds the M-length of a Euclidean unit vector
  for (const auto& M : run.field.metrics) lmax = std::max(lmax, largest_eigenvalue_above(M));
  const auto& sites = r.mesh.sites;
  const std::size_t first = sites.size() - r.trace.size();  // the corners come first, untraced
  const auto dist = [&](std::size_t u, std::size_t v) {
    return std::sqrt(std::min(approx_d2l(r.mesh.metrics[u], sites[u], sites[v]), approx_d2l(r.mesh.metrics[v], sites[u], sites[v])));
  };
  long double m = INFINITY;
  std::optional<Rational> m2;  // m², exactly
  for (std::size_t u = 0; u < first; ++u)
    for (std::size_t v = u + 1; v < first; ++v) {
      m = std::min(m, dist(u, v));
      if (const Rational x = d2_between(run.r, u, v); !m2 || x < *m2) m2 = x;
    }
  const Rational lfs_over_gamma2 = run.delta2 / (4 * Rational(run.gamma_hi) * Rational(run.gamma_hi));
  std::array<int, 9> checked{};
  int without_lemma = 0;
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    const auto& t = r.trace[k];
    const std::size_t z = first + k;
    RC_ASSERT(sites[z].x == t.x && sites[z].y == t.y);
    long double nearest = INFINITY;
    for (std::size_t w = 0; w < z; ++w) nearest = std::min(nearest, dist(z, w));
    // Exactly for the sites within 10⁻⁶ of the nearest in long double (more than its rounding).
    std::optional<Rational> nearest2;
    for (std::size_t w = 0; w < z; ++w)
      if (dist(z, w) <= nearest * (1 + 1e-6L))
        if (const Rational x = d2_between(run.r, z, w); !nearest2 || x < *nearest2) nearest2 = x;
    RC_LOG() << "insertion " << k << " (site " << z << ") rule " << t.rule << " for rule " << t.for_rule << " at (" << t.x << ", " << t.y << "), nearest " << nearest
             << ", m " << m << "\n";
    if (t.rule == 1) RC_ASSERT(*nearest2 >= std::min(*m2, lfs_over_gamma2));  // Lemma 17
    const bool ls_violator = t.for_rule == 3 || t.for_rule == 7;
    if (t.rule == 2 && ls_violator) RC_ASSERT(*nearest2 >= *m2);  // Lemma 23
    if (t.rule == 3 || t.rule == 7) {  // Lemma 21
      const long double e = std::sqrt(lmax) * t.displacement;
      RC_ASSERT(nearest >= (g_lo * std::sqrt(g_lo * g_lo + 1) * m - e) * (1 - 1e-12L));
      // Lemma 18's premise: q is a Voronoi vertex, at r from three sites in their metrics and no
      // nearer to any other (r̃, the trace's radius, is one of the three's distance at q̃).
      std::size_t at_r = 0;
      for (std::size_t w = 0; w < z; ++w) {
        const long double d = std::sqrt(approx_d2l(r.mesh.metrics[w], sites[z], sites[w]));
        RC_ASSERT(d >= (t.radius - 2 * e) * (1 - 1e-12L));
        if (d <= (t.radius + 2 * e) * (1 + 1e-12L)) ++at_r;
      }
      RC_ASSERT(at_r >= 3u);
    }
    if (t.rule == 5 || t.rule == 6 || t.rule == 8 || (t.rule == 2 && !ls_violator))
      ++without_lemma;
    else
      ++checked[static_cast<std::size_t>(t.rule)];
    m = std::min(m, nearest);
    m2 = std::min(*m2, *nearest2);
  }
  RC_TAG(run.field.kind);
  RC_CLASSIFY(checked[1] > 0, "rule 1 checked");
  RC_CLASSIFY(checked[2] > 0, "rule 2 checked");
  RC_CLASSIFY(checked[3] > 0, "rule 3 checked");
  RC_CLASSIFY(checked[7] > 0, "rule 7 checked");
  RC_CLASSIFY(without_lemma > 0, "a rule without a lemma (inverted, island, tie, or a split for one)");
}

// The filters (FilterInterval boxes of Voronoi vertices for containment in Ω and the size rule,
// the diametral-ellipse test that discards sites before the cells along a subsegment are
// computed) only speed the refiner up: with them off, every decision in rationals, a run makes
// the same insertions and ends with the same mesh, double for double.
// LS Lemma 12 on the traces of runs on the linear field (any θ_bound, a size rule or none: the
// lemma holds in any Voronoi diagram). For each inserted site z (any rule: z is a point of some
// cell), v the earlier site whose cell holds it (least d_v(z), LS §3's cells in each site's own
// metric, exactly) and γ ∈ {5/4, 3/2, 2}: when d_v(z) ≥ bdr(v, γ), every earlier site w has
// d(w, z) = min{d_w(z), d_z(w)} ≥ bdr_min(γ)/γ. bdr(v, γ) is bounded above by a witness, a point
// q* of closed Ω on the vertical through v with τ(v, q*) > γ decided exactly on the metrics the
// field gives at both (the candidates: h = γ(1 + 2⁻²⁰)h_v and h_v/(γ(1 + 2⁻²⁰)), on either side of
// y = ½); bdr_min(γ) is bounded below by LinearField::bdr_min_below. So the premise is certain
// where it is asserted, and the conclusion is decided exactly. Unlike Theorem 11's μ, the bound is
// near the sites' spacing: the tags count the insertions where the premise held.
RC_GTEST_PROP(LS_L12, InsertionFarInItsCellKeepsBdrMinOverGamma, ()) {
  const LinearField f = linear_field();
  refiners::ls::LsParameters p;
  p.theta_bound = *rc::gen::elementOf(std::vector<double>{5, 10, 15, 20});
  p.size = *rc::gen::elementOf(std::vector<double>{0, 0, 1, 2});
  p.max_vertices = 400, p.max_seconds = 1e9;
  const auto corners = gen::random_domain(*rc::gen::arbitrary<bool>(), true);
  const Rational gamma = *rc::gen::elementOf(std::vector<Rational>{Rational(5, 4), Rational(3, 2), Rational(2)});
  const auto r = refiners::ls::refine_ls(refiners::common::Domain(corners), f.field, p);
  RC_LOG() << r.stop_reason << "\n";
  const auto& sites = r.mesh.sites;
  const auto at = [&](std::size_t u) { return predicates::Point2<Rational>{Rational(sites[u].x), Rational(sites[u].y)}; };
  const Rational bound = f.bdr_min_below(gamma) / gamma, bound2 = bound * bound, step = 1 + Rational(std::ldexp(1.0, -20));
  // bdr(v, γ)², bounded above by the nearest witness; nothing when none is found.
  const auto bdr2_above = [&](std::size_t v) {
    const auto& Mv = r.mesh.metrics[v];
    const Rational hv = f.h(at(v).y);
    std::optional<Rational> least;
    for (const Rational& target : {gamma * step * hv, hv / (gamma * step)})
      for (const int side : {-1, 1}) {
        if (target < Rational(f.h0)) continue;
        const double y = (Rational(1, 2) + side * (target - Rational(f.h0)) / f.k).convert_to<double>();
        if (!geometry::in_closed_polygon(predicates::Point2<double>{sites[v].x, y}, corners)) continue;
        const auto Mq = f.field.at(sites[v].x, y);
        RC_ASSERT(Mq.m11 == Mv.m11 && Mq.m12 == 0 && Mv.m12 == 0);
        const Rational a(Mv.m22), b(Mq.m22);
        if (!(a > gamma * gamma * b || b > gamma * gamma * a)) continue;  // τ(v, q*) ≤ γ: no witness
        const Rational d2 = a * (Rational(y) - at(v).y) * (Rational(y) - at(v).y);
        if (!least || d2 < *least) least = d2;
      }
    return least;
  };
  const std::size_t first = sites.size() - r.trace.size();
  int premise_held = 0;
  double least_ratio = INFINITY;  // d(w, z)/bound where the premise held: how much room the lemma leaves
  for (std::size_t z = first; z < sites.size(); ++z) {
    std::size_t v = 0;
    std::optional<Rational> dv2;
    for (std::size_t w = 0; w < z; ++w)
      if (const Rational d = d2(exact(r.mesh.metrics[w]), at(w), at(z)); !dv2 || d < *dv2) dv2 = d, v = w;
    const auto bdr2 = bdr2_above(v);
    if (!bdr2 || *dv2 < *bdr2) continue;
    ++premise_held;
    for (std::size_t w = 0; w < z; ++w) {
      const Rational d = d2_between(r, z, w);
      RC_ASSERT(d >= bound2);
      least_ratio = std::min(least_ratio, std::sqrt((d / bound2).convert_to<double>()));
    }
  }
  RC_TAG(premise_held == 0 ? "premise never held" : premise_held < 5 ? "premise held 1 to 4 times" : "premise held 5 times or more");
  if (premise_held > 0) RC_TAG(least_ratio < 1.5 ? "closest under 1.5 times the bound" : least_ratio < 3 ? "closest 1.5 to 3 times the bound" : "closest 3 times the bound or more");
}

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
  const Rational s2 = gen::sin2_above(run.p.theta_bound), size2 = rational_from_double(run.p.size) * rational_from_double(run.p.size);
  const Rational det = M.m11 * M.m22 - M.m12 * M.m12;
  std::size_t exempt = 0;  // below θ_bound across a small input angle, which rule 3 leaves (corner_shells.hpp)
  for (const auto& t : r.mesh.triangles) {
    const auto &a = m.sites[t[0]], &b = m.sites[t[1]], &c = m.sites[t[2]];
    bool poor = false;
    for (int i = 0; i < 3; ++i)
      poor = poor || !predicates::angle_at_least_arcsin(m.sites[t[(i + 2) % 3]], m.sites[t[i]], m.sites[t[(i + 1) % 3]], M, s2);
    if (poor) {
      RC_ASSERT(gen::exempt_at_small_angle(m, *run.X, t));
      ++exempt;
    }
    if (run.p.size > 0) {
      // Circumradius in M, R = ℓ_ab ℓ_bc ℓ_ca / (4 K_M), K_M = √det M · |orient| / 2:
      // R² <= size² ⇔ ℓ_ab² ℓ_bc² ℓ_ca² <= 4 size² det M orient².
      const Rational orient = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      RC_ASSERT(d2(M, a, b) * d2(M, b, c) * d2(M, c, a) <= 4 * size2 * det * orient * orient);
    }
  }
  RC_ASSERT(exempt == r.exempt_left);
  RC_CLASSIFY(exempt > 0, "triangles left at a small input angle");
  gen::assert_pslg_segments_are_edges(m, *run.X);
}
