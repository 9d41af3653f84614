// The star refiner's throughput (issue 6 target: at least 50k vertices per second) on the unit
// square: the linear boundary-layer field and the hyperbolic shock field (α = 3, and the default
// α = 9), at sizes around 10k and 100k vertices (the field parameter sets the size; the count is
// reported). Default refinement parameters (ρ₀ = 3, γ₀ = 1.5, δ = 0.1, Pick_valid on).
// Run: build/bin/refiner_bench (figures in docs/bench.md).
#include "predicates/filtered_sign.hpp"
#include "fields/registry.hpp"
#include "refiners/star/star_refiner.hpp"

#include <benchmark/benchmark.h>

using namespace anisocert::refiners::star;
using anisocert::fields::make_field;
using anisocert::fields::MetricField;

namespace {

void refine(benchmark::State& state, const char* field, const char* param, double value, double alpha) {
  std::map<std::string, double> params{{param, value}};
  if (alpha > 0) params["alpha"] = alpha;
  const MetricField f = make_field(field, params);
  RefineParameters p;
  p.max_vertices = 400000, p.max_seconds = 600;
  StarResult r;
  const auto before = anisocert::predicates::filter_stats();
  for (auto _ : state) r = refine_star({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, f, p);
  // Predicate calls the static filter could not decide (interval stage), and those the interval
  // could not either (exact rationals), per vertex.
  const auto after = anisocert::predicates::filter_stats();
  state.counters["interval_per_vertex"] = static_cast<double>(after.interval_stage - before.interval_stage) / r.mesh.sites.size();
  state.counters["exact_per_vertex"] = static_cast<double>(after.exact_stage - before.exact_stage) / r.mesh.sites.size();
  state.counters["vertices"] = static_cast<double>(r.mesh.sites.size());
  state.counters["vertices_per_s"] = r.mesh.sites.size() / r.seconds;
  state.counters["consistent"] = r.consistent;
}

}  // namespace

BENCHMARK_CAPTURE(refine, linear_10k, "linear", "hx", 0.01, 0)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, linear_100k, "linear", "hx", 0.0035, 0)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, linear_250k, "linear", "hx", 0.002, 0)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_10k, "shock", "h", 0.01, 3)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_100k, "shock", "h", 0.0037, 3)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_350k, "shock", "h", 0.002, 3)->Iterations(1)->Unit(benchmark::kSecond);
// The default shock field (α = 9, 10:1 anisotropy): distortion and inconsistency insertions,
// not the size, set the count (about 43k at the default h = 0.05).
BENCHMARK_CAPTURE(refine, shock_default_43k, "shock", "h", 0.05, 0)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(refine, shock_default_100k, "shock", "h", 0.0065, 0)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
