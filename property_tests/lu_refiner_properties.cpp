// The star refiner (refiners/star/) on random runs, named by CATALOG ID. LU.A41: a run whose stars
// are consistent merges into a mesh the exact certifier accepts (valid, locally uniform,
// radius-edge ≤ ρ₀ and distortion ≤ γ₀ decided without rounding). LU.L41–L44: every site inserted
// by rules 2–5 lies in the picking region B_{M_v}(c, δr) of an empty circumellipse, so every
// earlier site is at M_v-distance ≥ (1 − δ) r: the insertion-radius bound all four lemmas start
// from, checked on the run's trace against every earlier site (not only the star's).
// LU.T45: parameters meeting Theorem 4.5's decided conditions, on a constant field and a domain
// meeting Lemma 4.1, terminate with the bounds.
#include "io/mesh_output.hpp"
#include "oracle/mesh_certifier.hpp"
#include "refiners/star/star_refiner.hpp"
#include "theory/lu_theorem45.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

using namespace anisocert;
using refiners::star::RefineParameters;
using refiners::star::RefineResult;

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
};

Run random_run() {
  Run run;
  const int domain = *rc::gen::inRange(0, 2);
  const int kind = *rc::gen::inRange(0, 3);
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
  run.r = refiners::star::refine_star(kDomains[domain], refiners::star::make_field(run.field, params), run.p);
  return run;
}

oracle::CertifyReport certify(const Run& run) {
  oracle::CertifyOptions o;
  o.rho0 = rational_from_double(run.p.rho0), o.gamma0 = rational_from_double(run.p.gamma0);
  const auto& r = run.r;
  return oracle::certify_mesh(io::exact_mesh({r.sites, r.metrics, r.domain, r.segments, r.triangles}), o);
}

}  // namespace

RC_GTEST_PROP(LU_A41, ConsistentStarsMergeIntoACertifiedMesh, ()) {
  const Run run = random_run();
  RC_TAG(run.field, run.r.consistent ? "consistent" : "stopped", run.r.acute_corners.empty() ? "Lemma 4.1 holds" : "acute corner");
  if (!run.r.consistent) {
    RC_ASSERT(run.r.stop_reason.find("budget") != std::string::npos || run.r.stop_reason.find("LU Lemma 4.1") != std::string::npos);
    return;
  }
  if (!run.r.acute_corners.empty()) return;
  const oracle::CertifyReport c = certify(run);
  RC_ASSERT(c.valid_holds());
  RC_ASSERT(c.uniform_violations.empty());
  RC_ASSERT(c.rho_violations.empty());
  RC_ASSERT(c.gamma_violations.empty());
}

RC_GTEST_PROP(LU_L41_L44, InsertionRadiusOnTheTrace, ()) {
  const Run run = random_run();
  const auto& r = run.r;
  const std::size_t first = r.sites.size() - r.trace.size();  // the corners come first, untraced
  int checked = 0;
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    const auto& t = r.trace[k];
    if (t.rule == refiners::star::encroachment) continue;
    const auto& M = r.metrics[t.star];
    const double bound = (1 - run.p.delta) * t.radius * (1 - 1e-9);  // relative slack: r itself is a double
    for (std::size_t s = 0; s < first + k; ++s) {
      const double dx = r.sites[s].x - t.x, dy = r.sites[s].y - t.y;
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
  const auto field = refiners::star::make_field("constant", {{"m11", a}, {"m12", *rc::gen::inRange(-2, 3) * 0.5}, {"m22", c}});
  Run run{p, refiners::star::refine_star(kDomains[0], field, p), "constant"};
  RC_PRE(run.r.acute_corners.empty());
  RC_TAG(run.r.sites.size() < 100 ? "under 100 vertices" : "100 vertices or more");
  RC_ASSERT(run.r.consistent);
  const oracle::CertifyReport cert = certify(run);
  RC_ASSERT(cert.valid_holds());
  RC_ASSERT(cert.uniform_violations.empty());
  RC_ASSERT(cert.rho_violations.empty());
  RC_ASSERT(cert.gamma_violations.empty());
}
