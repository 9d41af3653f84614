// The exact diagram's cost and how it grows (issue 5 targets: n = 200 in under 5 s, n = 1000 in
// under 60 s, memory under 2 GB): uniformly random sites in the unit square with metrics whose
// eigen-directions turn with x and whose anisotropy (ratio of unit-ball axes) varies smoothly
// from 1:1 to 10:1 with y. Each phase's time is reported as a counter (seconds).
// Run: build/bin/diagram_bench (figures in docs/bench.md); peak memory: /usr/bin/time -v.
#include "oracle/diagram/diagram.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

using anisocert::Rational;
using namespace anisocert::oracle;

namespace {

Mesh<Rational> random_input(int n, unsigned seed) {
  Mesh<Rational> in;
  in.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(1, 99999);
  auto exact = [](double v) { return Rational(static_cast<long>(std::lround(v * 1000)), 1000); };
  for (int i = 0; i < n; ++i) {
    const Rational x(coord(rng), 100000), y(coord(rng), 100000);
    bool duplicate = false;
    for (const auto& p : in.sites) duplicate = duplicate || (p.x == x && p.y == y);
    if (duplicate) continue;
    const double xd = x.convert_to<double>(), yd = y.convert_to<double>();
    const double angle = M_PI * xd, ratio = 1 + 9 * std::pow(std::sin(M_PI * yd / 2), 2);
    const double c = std::cos(angle), s = std::sin(angle), l1 = ratio * ratio, l2 = 1;
    in.sites.push_back({x, y});
    in.metrics.push_back({exact(l1 * c * c + l2 * s * s), exact((l1 - l2) * c * s), exact(l1 * s * s + l2 * c * c)});
  }
  return in;
}

void diagram(benchmark::State& state) {
  const Mesh<Rational> in = random_input(static_cast<int>(state.range(0)), 2026);
  Diagram d;
  for (auto _ : state) d = compute_diagram(in);
  state.counters["candidates_s"] = d.stats.seconds_candidates;
  state.counters["vertices_s"] = d.stats.seconds_vertices;
  state.counters["arcs_s"] = d.stats.seconds_arcs;
  state.counters["faces_s"] = d.stats.seconds_faces;
  state.counters["dual_s"] = d.stats.seconds_dual;
  state.counters["triples"] = static_cast<double>(d.stats.triples);
  state.counters["pairs"] = static_cast<double>(d.stats.pairs);
  state.counters["vertices"] = static_cast<double>(d.nodes.size());
  state.counters["arcs"] = static_cast<double>(d.arcs.size());
}

}  // namespace

BENCHMARK(diagram)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
