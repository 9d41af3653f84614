// The 3D star refiner (refiners/star/star_refiner3.hpp, issue 40) on random small runs, named by
// CATALOG ID, lu_refiner_properties.cpp's 3D counterpart. One property per run, since each run
// costs a tenth of a second:
//  - LU.A41 in 3D: a run whose stars are consistent merges into a mesh the exact 3D certifier
//    accepts (oracle/, which shares no code with refiners/): a valid tetrahedralization, locally
//    uniform, radius-edge ratio ≤ ρ₀ in every vertex's metric and distortion ≤ γ₀, all decided
//    without rounding; a run that is not consistent says why.
//  - LU.L41–L44 in 3D: every site inserted by rules 2–5 lies in the picking region B_{M_v}(c, δr)
//    of the M_v-circumsphere of a tetrahedron of the star S_v, which holds no site, so every
//    earlier site is at M_v-distance ≥ (1 − δ) r: the insertion radius LU's Lemmas 4.1–4.4 start
//    from, checked on the run's trace against every earlier site (not only the star's). The
//    centroids that stand in for a point picked outside Ω (Insertion3::stand_in) are not Refine(τ)
//    and are counted apart.
// Domains: boxes, a triangular prism and an L-shaped prism (a reflex ridge), dyadic sizes from 1/2
// to 1; fields: constant M = LLᵀ, L lower triangular with small integer entries (rotated and
// stretched up to about 8 : 1); random ρ₀, γ₀, δ and seed.
#include "geometry/builtin_polyhedra.hpp"
#include "oracle/certify/mesh_certifier3.hpp"
#include "refiners/star/rules.hpp"
#include "refiners/star/star_refiner3.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

using namespace anisocert;
using predicates::Sym3;
using refiners::star::RefineParameters;

namespace {

struct Run3 {
  RefineParameters p;
  refiners::star::StarResult3 r;
  std::string shape;
};

Run3 random_run3() {
  Run3 run;
  const auto size = [] { return Rational(*rc::gen::inRange(2, 5), 4); };  // 1/2 … 1
  const Rational w = size(), h = size(), d = size();
  const int shape = *rc::gen::elementOf(std::vector<int>{0, 1, 2});
  geometry::Polyhedron polyhedron;
  if (shape == 0) {
    polyhedron = geometry::prism_polyhedron({{0, 0}, {w, 0}, {w, h}, {0, h}}, d), run.shape = "box";
  } else if (shape == 1) {
    polyhedron = geometry::prism_polyhedron({{0, 0}, {w, 0}, {w / 4, h}}, d), run.shape = "triangular prism";
  } else {
    polyhedron = geometry::prism_polyhedron({{0, 0}, {w, 0}, {w, h / 2}, {w / 2, h / 2}, {w / 2, h}, {0, h}}, d), run.shape = "L-shaped prism";
  }
  const auto entry = [](int lo, int hi) { return static_cast<double>(*rc::gen::inRange(lo, hi + 1)); };
  const double l1 = entry(3, 5), l2 = entry(3, 5), l3 = entry(3, 5), l21 = entry(-1, 1), l31 = entry(-1, 1), l32 = entry(-1, 1);
  const Sym3<double> M{l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32, l31 * l31 + l32 * l32 + l3 * l3};
  const fields::MetricField3 field{"constant", {}, [M](double, double, double) { return M; }};
  run.p.rho0 = 2.5 + *rc::gen::inRange(0, 16) * 0.1;
  run.p.gamma0 = 1.2 + *rc::gen::inRange(0, 9) * 0.1;
  run.p.delta = 0.02 + *rc::gen::inRange(0, 10) * 0.02;
  run.p.seed = *rc::gen::inRange(0, 1 << 20);
  run.p.size = *rc::gen::elementOf(std::vector<double>{0.5, 0.75, 1});  // rule 4 at work
  run.p.seed_interior = *rc::gen::arbitrary<bool>();  // without seeds, rules 2–5 place every interior site
  run.p.max_vertices = 400, run.p.max_seconds = 0.5;
  run.r = refiners::star::refine_star3(refiners::common::Domain3(polyhedron), field, run.p);
  return run;
}

}  // namespace

RC_GTEST_PROP(LU_A41_L41_3D, ConsistentRunsAreCertifiedAndKeepTheInsertionRadius, ()) {
  const Run3 run = random_run3();
  const auto& r = run.r;
  RC_TAG(run.shape, r.consistent ? "consistent" : "stopped: " + r.stop_reason.substr(0, r.stop_reason.find(' ', 10)));
  RC_LOG() << run.shape << ", " << r.mesh.vertices.size() << " vertices, stop: " << r.stop_reason << "\n";
  // LU.L41–L44: the insertion radius, against every earlier site.
  const std::size_t first = r.mesh.vertices.size() - r.trace.size();  // Ω's vertices and the seeds, untraced
  std::size_t checked = 0, stand_ins = 0;
  for (std::size_t k = 0; k < r.trace.size(); ++k) {
    const auto& t = r.trace[k];
    if (t.rule == static_cast<int>(refiners::star::Rule::encroachment)) continue;
    if (t.stand_in) {
      ++stand_ins;
      continue;
    }
    const Sym3<double>& M = r.mesh.metrics[t.site];
    // Slack: r is the refiner's double (relative 10⁻⁹) and the picked point is rounded to doubles.
    const double bound = (1 - run.p.delta) * t.radius * (1 - 1e-9);
    for (std::size_t s = 0; s < first + k; ++s) {
      const auto& q = r.mesh.vertices[s];
      const double distance = std::sqrt(predicates::quadratic_form(M, q.x - t.p.x, q.y - t.p.y, q.z - t.p.z));
      if (!(distance >= bound)) RC_LOG() << "insertion " << k << " (rule " << t.rule << ", r = " << t.radius << ") is " << distance << " from site " << s << "\n";
      RC_ASSERT(distance >= bound);
    }
    ++checked;
  }
  RC_CLASSIFY(checked > 0, "insertions by rules 2-5 checked");
  RC_CLASSIFY(stand_ins > 0, "centroids stood in");
  // LU.A41: a consistent run is certified; another says why it stopped.
  if (!r.consistent) {
    RC_ASSERT(!r.stop_reason.empty());
    RC_ASSERT(r.stop_reason != "all stars consistent");  // the reason is not a claim of success
    return;
  }
  const auto R = [](double x) { return rational_from_double(x); };
  geometry::Mesh3<Rational> exact;
  for (const auto& q : r.mesh.vertices) exact.vertices.push_back({R(q.x), R(q.y), R(q.z)});
  for (const auto& N : r.mesh.metrics) exact.metrics.push_back({R(N.m11), R(N.m12), R(N.m13), R(N.m22), R(N.m23), R(N.m33)});
  exact.tetrahedra = r.mesh.tetrahedra, exact.triangles = r.mesh.triangles;
  oracle::Certify3Options o;
  o.rho0 = R(run.p.rho0), o.gamma0 = R(run.p.gamma0), o.threads = 1;
  const oracle::Certify3Report c = oracle::certify_mesh3(exact, o);
  RC_ASSERT(c.valid_holds());
  RC_ASSERT(c.uniform_violations.empty());
  RC_ASSERT(c.rho_violations.empty());
  RC_ASSERT(c.gamma_violations.empty());
}
