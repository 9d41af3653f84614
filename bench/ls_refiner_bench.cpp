// The LS refiner's throughput on fields whose sites have different metrics (issue 16's target: at
// least 20k vertices per second), on the unit square: the linear boundary-layer field (default
// hx = 0.1, h0 = 10⁻³) and the shock field (default α = 9, δ = 0.6, h = 0.05), at θ_bound = 20°,
// with the size bound set so that the runs have about 10k and 100k vertices (the count is reported;
// the refinement on the shock field is driven by the field's variation, unwedged and inverted
// vertices, as much as by the size). Also the same runs with LS §9's M′ (--normalized-metric).
// Run: build/bin/ls_refiner_bench (figures in docs/bench.md).
#include "fields/registry.hpp"
#include "refiners/ls/ls_refiner.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace anisocert;

void refine(benchmark::State& state, const char* field, double size, bool normalized) {
  const fields::MetricField f = fields::make_field(field, {});
  refiners::ls::LsParameters p;
  p.theta_bound = 20, p.size = size, p.normalized_metric = normalized;
  p.max_vertices = 400000, p.max_seconds = 900;
  refiners::ls::LsResult r;
  for (auto _ : state) r = refiners::ls::refine_ls(refiners::common::Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), f, p);
  state.counters["vertices"] = static_cast<double>(r.mesh.sites.size());
  state.counters["vertices_per_s"] = static_cast<double>(r.mesh.sites.size()) / r.seconds;
  state.counters["finished"] = r.consistent;
}

}  // namespace

BENCHMARK_CAPTURE(refine, linear_10k, "linear", 0.15, false)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, linear_100k, "linear", 0.05, false)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_10k, "shock", 0.5, false)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_100k, "shock", 0.1, false)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_10k_normalized, "shock", 0.5, true)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, linear_10k_normalized, "linear", 0.15, true)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
