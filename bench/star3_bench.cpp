// The first pieces of the 3D star refiner (issue 40): one star wrapped from scratch
// (refiners/star/gift_wrap3.hpp) among the 124 other sites of a 5 × 5 × 5 block around it, and a
// star kept by inserting a site (star_update3.hpp). Sites: the integer lattice (every cube's
// corners cospherical under I and diag(1, 4, 9): the perturbation decides) or the lattice moved
// at random by up to 0.3 (generic). Issue 40's target is 20,000 vertices/s for the whole refiner;
// an insertion changes a few dozen stars and wraps one.
// And the whole refiner (star_refiner3.hpp) on the cube, side by side: a constant isotropic field
// (100 I: edges of 0.1) and UGAWG's linear field with h0 = 0.1, 0.06, 0.05, 0.02 and its README's
// 10⁻³ (minutes), each run to the end; counters: vertices per second, and the
// tetrahedra against a unit mesh's (∫√det M over the cube, closed form here, divided by the
// volume of the unit regular tetrahedron, √2/12).
// Run: build/bin/star3_bench (figures in docs/bench.md).
#include "geometry/builtin_polyhedra.hpp"
#include "refiners/star/gift_wrap3.hpp"
#include "refiners/star/star_refiner3.hpp"
#include "refiners/star/star_update3.hpp"

#include <cmath>

#include <benchmark/benchmark.h>

#include <random>

using anisocert::predicates::Point3;
using anisocert::predicates::Sym3;
using namespace anisocert::refiners::star;

namespace {

// The 5 × 5 × 5 block around the origin (site 0 is the origin), moved by up to `jitter`.
std::vector<Point3<double>> block(double jitter) {
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> move(-jitter, jitter);
  std::vector<Point3<double>> p{{0, 0, 0}};
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y)
      for (int z = -2; z <= 2; ++z)
        if (x || y || z) p.push_back({x + move(rng), y + move(rng), z + move(rng)});
  return p;
}

const Sym3<double>& metric(int k) {
  static const Sym3<double> identity{1, 0, 0, 1, 0, 1}, stretched{1, 0, 0, 4, 0, 9};
  return k == 0 ? identity : stretched;
}

void wrap(benchmark::State& state) {
  const auto p = block(state.range(0) ? 0.3 : 0);
  const Sym3<double>& M = metric(static_cast<int>(state.range(1)));
  std::vector<int> candidates;
  for (int i = 1; i < static_cast<int>(p.size()); ++i) candidates.push_back(i);
  Star3 s;
  for (auto _ : state) benchmark::DoNotOptimize(s = gift_wrap_star3(0, candidates, p, M));
  state.counters["stars_per_s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["tetrahedra"] = static_cast<double>(s.link.size());
}

// A site inserted near the origin (inside its conflict zone), into the star kept from before.
void insert(benchmark::State& state) {
  auto p = block(state.range(0) ? 0.3 : 0);
  const Sym3<double>& M = metric(static_cast<int>(state.range(1)));
  std::vector<int> candidates;
  for (int i = 1; i < static_cast<int>(p.size()); ++i) candidates.push_back(i);
  const Star3 before = gift_wrap_star3(0, candidates, p, M);
  p.push_back({0.375, 0.25, 0.125});
  const int k = static_cast<int>(p.size()) - 1;
  Star3 s;
  for (auto _ : state) {
    s = before;
    if (insert_into_star3(s, 0, k, p, M) != Star3Update::updated) state.SkipWithError("the star was not updated in place");
  }
  state.counters["insertions_per_s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

// range(0): 0 the constant field 100 I; else UGAWG linear with h0 = range(0) / 1000.
void refine(benchmark::State& state) {
  static const anisocert::refiners::common::Domain3 cube(anisocert::geometry::cube_polyhedron());
  const double h0 = state.range(0) / 1000.0;
  anisocert::fields::MetricField3 field{"bench", {}, [h0](double, double, double z) {
                                          const double hz = h0 > 0 ? h0 + 2 * (0.1 - h0) * std::abs(z - 0.5) : 0.1;
                                          return Sym3<double>{100, 0, 0, 100, 0, 1 / (hz * hz)};
                                        }};
  // ∫√det M = 100 ∫ dz / hz: 1000 for hz = 0.1, else 2 · 100 · ln(0.1 / h0) / (2 (0.1 − h0)).
  const double integral = h0 > 0 && h0 < 0.1 ? 100 * std::log(0.1 / h0) / (0.1 - h0) : 1000;
  const double unit_tetrahedra = integral / (std::sqrt(2.0) / 12);
  RefineParameters p;
  p.max_seconds = 600;
  std::size_t vertices = 0, tetrahedra = 0;
  bool consistent = true;
  for (auto _ : state) {
    const StarResult3 r = refine_star3(cube, field, p);
    vertices += r.mesh.vertices.size(), tetrahedra += r.mesh.tetrahedra.size();
    consistent = consistent && r.consistent;
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["vertices"] = vertices / runs;
  state.counters["vertices/s"] = benchmark::Counter(static_cast<double>(vertices), benchmark::Counter::kIsRate);
  state.counters["tets/unit"] = tetrahedra / runs / unit_tetrahedra;
  state.counters["consistent"] = consistent;
}

BENCHMARK(wrap)->ArgNames({"jitter", "metric"})->Args({0, 0})->Args({1, 0})->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(insert)->ArgNames({"jitter", "metric"})->Args({0, 0})->Args({1, 0})->Args({1, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(refine)->ArgName("h0x1000")->Arg(0)->Arg(100)->Arg(60)->Arg(50)->Arg(20)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_MAIN();
