// The star refiner (refiners/star/) on random runs, named by CATALOG ID. LU.A41: a run whose stars
// are consistent merges into a mesh the exact certifier accepts (valid, locally uniform,
// radius-edge ≤ ρ₀ and distortion ≤ γ₀ decided without rounding). LU.L41–L44: every site inserted
// by rules 2–5 lies in the picking region B_{M_v}(c, δr) of an empty circumellipse, so every
// earlier site is at M_v-distance ≥ (1 − δ) r: the insertion-radius bound all four lemmas start
// from, checked on the run's trace against every earlier site (not only the star's).
// Domains: two fixed ones and random star-shaped polygons, convex or not (random_domain).
// LU.T45: parameters meeting Theorem 4.5's decided conditions, on a constant field and a domain
// meeting Lemma 4.1, terminate with the bounds.
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "property_tests/generators/domains.hpp"
#include "refiners/star/rules.hpp"
#include "refiners/star/star_refiner.hpp"
#include "theory/lu_theorem45.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

using namespace anisocert;
using refiners::star::RefineParameters;
using RefineResult = refiners::star::StarResult;

namespace {

using Polygon = std::vector<predicates::Point2<double>>;

// Domains whose corners are obtuse (Lemma 4.1 in near-isotropic metrics), coordinates exact doubles.
const std::vector<Polygon> kDomains = {
    {{1, -0.375}, {1, 0.375}, {0.375, 1}, {-0.375, 1}, {-1, 0.375}, {-1, -0.375}, {-0.375, -1}, {0.375, -1}},
    {{0, 0}, {2, 0}, {2.5, 1}, {1, 1.75}, {-0.5, 1}}};

struct Run {
  RefineParameters p;
  RefineResult r;
  std::string field;
  std::string domain = "fixed domain";
};

Run random_run() {
  Run run;
  // The two fixed domains, or a random one (2 in 3); elementOf does not scale with RapidCheck's
  // size as inRange does, which would keep the early cases on the fixed domains.
  const int choice = *rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5});
  const bool reflex = choice >= 4;
  const Polygon domain = choice < 2 ? kDomains[choice] : gen::random_domain(reflex);
  if (choice >= 2) run.domain = reflex ? "random non-convex" : "random convex";
  const int kind = *rc::gen::elementOf(std::vector<int>{0, 1, 2});  // constant, shock, radial
  std::map<std::string, double> params;
  if (kind == 0) {
    const double a = *rc::gen::inRange(10, 21), c = *rc::gen::inRange(10, 21);
    params = {{"m11", a}, {"m12", *rc::gen::inRange(-3, 4) * 0.5}, {"m22", c}};
    run.field = "constant";
  } else {
    params = {{"h", 0.3}, {"alpha", *rc::gen::inRange(0, 5) * 0.25}};
    run.field = kind == 1 ? "shock" : "radial";
  }
  run.p.rho0 = 2.2 + *rc::gen::inRange(0, 19) * 0.1;
  run.p.gamma0 = 1.2 + *rc::gen::inRange(0, 9) * 0.1;
  run.p.delta = 0.02 + *rc::gen::inRange(0, 10) * 0.02;
  run.p.seed = *rc::gen::inRange(0, 1 << 20);
  run.p.max_vertices = 1500, run.p.max_seconds = 1;
  run.r = refiners::star::refine_star(domain, fields::make_field(run.field, params), run.p);
  return run;
}

oracle::CertifyReport certify(const Run& run) {
  oracle::CertifyOptions o;
  o.rho0 = rational_from_double(run.p.rho0), o.gamma0 = rational_from_double(run.p.gamma0);
  const auto& r = run.r;
  return oracle::certify_mesh(geometry::exact(r.mesh), o);
}

}  // namespace

RC_GTEST_PROP(LU_A41, ConsistentStarsMergeIntoACertifiedMesh, ()) {
  const Run run = random_run();
  RC_TAG(run.field, run.domain, run.r.consistent ? "consistent" : "stopped", run.r.acute_corners.empty() ? "Lemma 4.1 holds" : "acute corner");
  // A stop names an accepted reason: a budget, a corner where Lemma 4.1 fails in the metric, or the
  // resolution of doubles. Endless refinement where Lemma 4.1 holds is a refiner failure.
  if (!run.r.consistent) {
    RC_LOG() << run.r.stop_reason;
    RC_ASSERT(run.r.stop_reason.find("budget") != std::string::npos ||
              run.r.stop_reason.find("not obtuse in the metric (LU Lemma 4.1") != std::string::npos ||
              run.r.stop_reason.find("finer than doubles resolve") != std::string::npos);
    return;
  }
  // (acute corners only threaten termination, LU Lemma 4.1: a consistent run is certified either way)
  const oracle::CertifyReport c = certify(run);
  RC_ASSERT(c.valid_holds());
  RC_ASSERT(c.uniform_violations.empty());
  RC_ASSERT(c.rho_violations.empty());
  RC_ASSERT(c.gamma_violations.empty());
}

RC_GTEST_PROP(LU_L41_L44, InsertionRadiusOnTheTrace, ()) {
  const Run run = random_run();
  const auto& r = run.r;
  RC_LOG() << run.field << ", " << run.domain << ", " << r.mesh.sites.size() << " sites, stop: " << r.stop_reason << "\n";
  for (const auto& q : r.mesh.domain) RC_LOG() << "(" << q.x << ", " << q.y << ") ";
  const std::size_t first = r.mesh.sites.size() - r.trace.size();  // the corners come first, untraced
  int checked = 0;
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    const auto& t = r.trace[k];
    if (t.rule == static_cast<int>(refiners::star::Rule::encroachment)) continue;
    const auto& M = r.mesh.metrics[t.site];
    // Slack: r itself is a double (relative 10⁻⁹), and the picked point is stored rounded to
    // doubles, half an ulp per coordinate, which moves it by at most √λ_max(M)·ulp in M's length
    // (this matters only for runs refined down to the resolution of doubles).
    const double lmax = (M.m11 + M.m22) / 2 + std::hypot((M.m11 - M.m22) / 2, M.m12);
    const double ulp = std::ldexp(1.0, std::ilogb(std::max(std::abs(t.x), std::abs(t.y))) - 52);
    const double bound = (1 - run.p.delta) * t.radius * (1 - 1e-9) - std::sqrt(lmax) * ulp;
    for (std::size_t s = 0; s < first + k; ++s) {
      const double dx = r.mesh.sites[s].x - t.x, dy = r.mesh.sites[s].y - t.y;
      if (!(std::sqrt(dx * (M.m11 * dx + M.m12 * dy) + dy * (M.m12 * dx + M.m22 * dy)) >= bound))
        RC_LOG() << "\ninsertion " << k << " rule " << t.rule << " at (" << t.x << ", " << t.y << "), r = " << t.radius << ", site " << s << "\n";
      RC_ASSERT(std::sqrt(dx * (M.m11 * dx + M.m12 * dy) + dy * (M.m12 * dx + M.m22 * dy)) >= bound);
    }
    ++checked;
  }
  RC_CLASSIFY(checked > 0, "insertions by rules 2-5 checked");
}

RC_GTEST_PROP(LU_T45, ConditionsGiveTerminationWithTheBounds, ()) {
  RefineParameters p;
  p.rho0 = 2.3 + *rc::gen::inRange(0, 18) * 0.1;
  p.delta = 0.01 + *rc::gen::inRange(0, 5) * 0.01;
  p.gamma0 = 1.01;
  p.beta = p.rho0;
  p.seed = *rc::gen::inRange(0, 1 << 20);
  p.max_vertices = 3000, p.max_seconds = 2;
  const theory::LuConditions conditions = theory::lu_t45_conditions(
      {rational_from_double(p.rho0), rational_from_double(p.gamma0), rational_from_double(p.delta), rational_from_double(p.beta)});
  RC_PRE(conditions.all());
  const double a = *rc::gen::inRange(10, 21), c = *rc::gen::inRange(10, 21);
  const auto field = fields::make_field("constant", {{"m11", a}, {"m12", *rc::gen::inRange(-2, 3) * 0.5}, {"m22", c}});
  Run run{p, refiners::star::refine_star(kDomains[0], field, p), "constant"};
  RC_PRE(run.r.acute_corners.empty());
  RC_TAG(run.r.mesh.sites.size() < 100 ? "under 100 vertices" : "100 vertices or more");
  RC_ASSERT(run.r.consistent);
  const oracle::CertifyReport cert = certify(run);
  RC_ASSERT(cert.valid_holds());
  RC_ASSERT(cert.uniform_violations.empty());
  RC_ASSERT(cert.rho_violations.empty());
  RC_ASSERT(cert.gamma_violations.empty());
}
