// The Labelle–Shewchuk refiner (refiners/ls/) certified by the exact oracle on every finished run
// (issue 16). Constant fields only so far: the refiner keeps the diagram of one metric.
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
#include "refiners/ls/ls_refiner.hpp"
#include "refiners/ls/theorem11_conditions.hpp"
#include "theory/ls_theorem11.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace anisocert;

namespace {

struct Run {
  refiners::ls::LsParameters p;
  refiners::ls::LsResult r;
  predicates::Sym2<double> M;
  std::string domain, separation;
};

// A random constant metric (eigenvalues 1 to 100, any orientation), a random domain (convex or
// not, with or without acute corners), θ_bound from 5° to 30° (above 20.7° Theorem 11 gives no
// guarantee) and a size bound or none.
Run random_run() {
  Run run;
  const bool reflex = *rc::gen::arbitrary<bool>(), obtuse = *rc::gen::arbitrary<bool>();
  const auto corners = gen::random_domain(reflex, obtuse);
  run.domain = std::string(reflex ? "non-convex" : "convex") + (obtuse ? "" : ", acute corners allowed");
  const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101), angle = *rc::gen::inRange(0, 180) * M_PI / 180;
  const double c = std::cos(angle), s = std::sin(angle);
  run.M = {l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c};
  run.p.theta_bound = *rc::gen::elementOf(std::vector<double>{5, 10, 15, 20, 20.5, 25, 30});
  run.p.size = *rc::gen::elementOf(std::vector<double>{0, 0.5, 1, 2});
  run.p.max_vertices = 600, run.p.max_seconds = 3;
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

Rational d2(const predicates::Sym2<Rational>& M, const predicates::Point2<Rational>& a, const predicates::Point2<Rational>& b) {
  const Rational x = a.x - b.x, y = a.y - b.y;
  return M.m11 * x * x + 2 * M.m12 * x * y + M.m22 * y * y;
}

}  // namespace

RC_GTEST_PROP(LS_S9, FinishedRunsAreTheDualOfTheExactDiagram, ()) {
  const Run run = random_run();
  const auto& r = run.r;
  const std::size_t n = r.mesh.sites.size();
  RC_TAG(run.domain, run.separation, r.consistent ? "finished" : "stopped", n < 50 ? "under 50 sites" : n < 200 ? "50 to 199 sites" : "200 sites or more");
  if (!r.consistent) {
    // A stop names a budget, or, where Theorem 11's conditions fail (refinement near acute
    // corners or above 20.7° need not end), the resolution of doubles.
    RC_LOG() << run.separation << ": " << r.stop_reason;
    RC_ASSERT(r.stop_reason.find("budget") != std::string::npos ||
              (run.separation != "separation holds" && r.stop_reason.find("no double point") != std::string::npos));
    return;
  }
  const geometry::Mesh<Rational> m = geometry::exact(r.mesh);
  const oracle::Diagram d = oracle::compute_diagram(m);
  for (const auto& f : d.faces) RC_ASSERT(!f.orphan);
  for (const auto& n : d.nodes) RC_ASSERT(n.wedged);
  for (const auto& a : d.arcs) RC_ASSERT(a.wedged);
  RC_ASSERT(d.theorem7.preconditions_hold);
  RC_ASSERT(d.dual_check.is_triangulation);
  const oracle::MeshDual dual = oracle::compare_with_dual(d, r.mesh.triangles, 3);
  for (const auto& w : dual.not_dual_witnesses) RC_LOG() << w.why << "\n";
  RC_ASSERT(dual.is_dual());

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
