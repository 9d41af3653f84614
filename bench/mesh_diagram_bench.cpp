// The exact diagram of a refined mesh's vertices (issue 14): the star refiner's mesh of the unit
// square for the demo's shock field (`anisocert demo`: h = 0.05, α = 3, ρ₀ = β = 5, γ₀ = 1.2; 6,165
// vertices), and the same field at h = 0.0038 (about 100,000 vertices). Targets: the 6,165-site
// mesh in at most 10 s (163 s with exact constructions before issue 14), the 100k-site mesh in at
// most 3 minutes with 2 cores and under 4 GB. Arguments: the field's h in units of 10⁻⁴, threads,
// exact-only (1) or filtered (0). Each phase's time is a counter (seconds).
// mesh_diagram_json/H/THREADS: the same diagram, then its JSON as `anisocert diagram --json` writes
// it (io::diagram_json, dumped): the diagram's seconds and the JSON's side by side (issue 38's
// target: the JSON adds at most the diagram's own time; it took 20 times as long before the
// second filter stage of oracle/algebraic/narrowed_box.hpp).
// Run: build/bin/mesh_diagram_bench (figures in docs/bench.md); peak memory: /usr/bin/time -v.
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "io/diagram_json.hpp"
#include "oracle/diagram/diagram.hpp"
#include "refiners/registry.hpp"

#include <benchmark/benchmark.h>

#include <chrono>

using anisocert::Rational;
using namespace anisocert;

namespace {

geometry::Mesh<Rational> refined(double h) {
  const refiners::RefinerEntry& star = *refiners::find_refiner("star");
  refiners::ParameterValues values = star.defaults();
  values["rho0"] = 5, values["beta"] = 5, values["gamma0"] = 1.2;
  refiners::common::Budget budget;
  budget.max_seconds = 600;
  const auto field = fields::make_field("shock", {{"h", h}, {"alpha", 3}});
  const refiners::Run run = star.run(refiners::common::Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), field, values, budget, 1, {});
  return geometry::exact(run.result.mesh);
}

void mesh_diagram(benchmark::State& state) {
  const geometry::Mesh<Rational> in = refined(static_cast<double>(state.range(0)) * 1e-4);
  oracle::DiagramOptions o;
  o.threads = static_cast<int>(state.range(1));
  o.exact_only = state.range(2) != 0;
  oracle::Diagram d;
  for (auto _ : state) d = oracle::compute_diagram(in, o);
  state.counters["sites"] = static_cast<double>(in.sites.size());
  state.counters["candidates_s"] = d.stats.seconds_candidates;
  state.counters["vertices_s"] = d.stats.seconds_vertices;
  state.counters["arcs_s"] = d.stats.seconds_arcs;
  state.counters["faces_s"] = d.stats.seconds_faces;
  state.counters["dual_s"] = d.stats.seconds_dual;
  state.counters["nodes"] = static_cast<double>(d.nodes.size());
  state.counters["exact_points"] = static_cast<double>(d.stats.filters.exact_points);
}

void mesh_diagram_json(benchmark::State& state) {
  const geometry::Mesh<Rational> in = refined(static_cast<double>(state.range(0)) * 1e-4);
  oracle::DiagramOptions o;
  o.threads = static_cast<int>(state.range(1));
  double diagram_s = 0, json_s = 0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const oracle::Diagram d = oracle::compute_diagram(in, o);
    const auto t1 = std::chrono::steady_clock::now();
    bytes = io::diagram_json(d).dump(1).size();
    const auto t2 = std::chrono::steady_clock::now();
    diagram_s = std::chrono::duration<double>(t1 - t0).count(), json_s = std::chrono::duration<double>(t2 - t1).count();
  }
  state.counters["sites"] = static_cast<double>(in.sites.size());
  state.counters["diagram_s"] = diagram_s;
  state.counters["json_s"] = json_s;
  state.counters["json_over_diagram"] = json_s / diagram_s;
  state.counters["json_MB"] = static_cast<double>(bytes) / 1e6;
}

}  // namespace

BENCHMARK(mesh_diagram_json)->Args({500, 1})->Args({500, 2})->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK(mesh_diagram)
    ->Args({500, 1, 0})->Args({500, 2, 0})->Args({500, 1, 1})->Args({38, 1, 0})->Args({38, 2, 0})
    ->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
