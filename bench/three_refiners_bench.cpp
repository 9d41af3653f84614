// The three refiners side by side (issue 17): the star refiner (LU), the Labelle–Shewchuk refiner
// and the Boissonnat–Wormser–Yvinec refiner on the unit square, each with its defaults and size 1
// (the largest circumradius in the metric, for all three), on five fields scaled so that the LS
// refiner makes a few thousand vertices: a constant metric diag(1100, 27500), the linear boundary
// layer (hx = 0.02, h0 = 0.002), the shock (h = 0.025), the radial layer (defaults) and a
// background mesh (the LS mesh of the linear field with hx = 0.05, h0 = 0.0125 at size 5, its
// metrics interpolated P1); and the BWY refiner alone on the shock field with h = 0.0125 (about
// 18,500 vertices), for its throughput. Counters per run: vertices, triangles, time and vertices
// per second (the refiner's own clock), and from the exact certifier (oracle/certify, metric checks
// on): the smallest angle in the vertices' metrics, the share of edges whose lengths in both ends'
// metrics lie in [1/√2, √2], the worst radius-edge ratio ρ and distortion γ over the triangles in
// its vertices' metrics (approximations of exact quantities); and whether the exact checks accept
// the mesh under each paper's own guarantee: the star refiner's a triangulation whose stars are
// consistent (certify: valid, locally uniform), LS's and BWY's a triangulation that is the dual of
// the exact diagram (the oracle's D|Ω), with Theorem 7's preconditions reported apart.
// Run: build/bin/three_refiners_bench --benchmark_counters_tabular=true (figures in docs/refiners.md).
#include "fields/background.hpp"
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "refiners/registry.hpp"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace anisocert;

const refiners::common::Domain& square() {
  static const refiners::common::Domain d({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  return d;
}

fields::MetricField field(const std::string& name) {
  if (name == "constant") return fields::make_field("constant", {{"m11", 1100}, {"m22", 27500}});
  if (name == "linear") return fields::make_field("linear", {{"hx", 0.02}, {"h0", 0.002}});
  if (name == "shock") return fields::make_field("shock", {{"h", 0.025}});
  if (name == "shock_fine") return fields::make_field("shock", {{"h", 0.0125}});
  if (name == "radial") return fields::make_field("radial", {});
  static const fields::MetricField background = [] {
    const refiners::RefinerEntry& ls = *refiners::find_refiner("ls");
    refiners::ParameterValues v = ls.defaults();
    v["size"] = 5;
    const auto run = ls.run(square(), fields::make_field("linear", {{"hx", 0.05}, {"h0", 0.0125}}), v, {}, 1, {});
    return fields::background_field(std::make_shared<fields::BackgroundMesh>(geometry::exact(run.result.mesh)), "background (LS mesh)");
  }();
  return background;
}

void refine(benchmark::State& state, const char* refiner, const char* field_name) {
  const refiners::RefinerEntry& entry = *refiners::find_refiner(refiner);
  refiners::ParameterValues values = entry.defaults();
  values["size"] = 1;
  refiners::common::Budget budget;
  budget.max_vertices = 400000, budget.max_seconds = 600;
  const fields::MetricField f = field(field_name);
  refiners::Run run;
  for (auto _ : state) run = entry.run(square(), f, values, budget, 1, {});
  const auto& r = run.result;
  state.counters["vertices"] = static_cast<double>(r.mesh.sites.size());
  state.counters["triangles"] = static_cast<double>(r.mesh.triangles.size());
  state.counters["refine_s"] = r.seconds;
  state.counters["vertices_per_s"] = static_cast<double>(r.mesh.sites.size()) / r.seconds;
  state.counters["finished"] = r.consistent;
  const geometry::Mesh<Rational> m = geometry::exact(r.mesh);
  oracle::CertifyOptions o;
  o.metric = true, o.uniform = !entry.dual_of_diagram;
  o.rho0 = Rational(1000000), o.gamma0 = Rational(1000000);  // measured, not judged
  const oracle::CertifyReport c = oracle::certify_mesh(m, o);
  state.counters["smallest_angle_deg"] = c.angles ? c.angles->smallest : 0;
  state.counters["unit_edge_share"] = c.lengths && c.lengths->edges > 0 ? static_cast<double>(c.lengths->unit_edges) / static_cast<double>(c.lengths->edges) : 0;
  state.counters["worst_rho"] = c.worst_rho;
  state.counters["worst_gamma"] = c.worst_gamma;
  bool accepted = r.consistent && c.valid_holds();  // a run that did not finish promises nothing
  if (entry.dual_of_diagram) {
    const oracle::Diagram d = oracle::compute_diagram(m);
    accepted = accepted && d.dual_check.is_triangulation && oracle::compare_with_dual(d, r.mesh.triangles, 0).is_dual();
    state.counters["theorem7_preconditions"] = d.theorem7.preconditions_hold;
  } else {
    accepted = accepted && c.uniform_violations.empty();
  }
  state.counters["certified"] = accepted;
}

}  // namespace

#define THREE(field)                                                                                         \
  BENCHMARK_CAPTURE(refine, star_##field, "star", #field)->Iterations(1)->Unit(benchmark::kSecond);          \
  BENCHMARK_CAPTURE(refine, ls_##field, "ls", #field)->Iterations(1)->Unit(benchmark::kSecond);              \
  BENCHMARK_CAPTURE(refine, bwy_##field, "bwy", #field)->Iterations(1)->Unit(benchmark::kSecond)

THREE(constant);
THREE(linear);
THREE(shock);
THREE(radial);
THREE(background);
BENCHMARK_CAPTURE(refine, bwy_shock_fine, "bwy", "shock_fine")->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
