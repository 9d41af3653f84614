// The tetrahedral certifier's throughput (issue 39 targets: at least 1 M tetrahedra/s for
// validity, 500 k/s for validity + edge lengths + local uniformity on a well-shaped mesh), side
// by side with reading the same mesh from a Medit file. Meshes: the Kuhn grid of n³ cubes
// (geometry/kuhn_grid.hpp), 6n³ tetrahedra.
//  - "delaunay": M = [[1, −¼, −¼], [−¼, 1, −¼], [−¼, −¼, 1]] at every vertex, for which the Kuhn
//    grid is strictly Delaunay (no vertex inside or on any tetrahedron's M-sphere: checked here,
//    the run fails otherwise), every tetrahedron well shaped in M (the main diagonal shortened);
//  - "ties": M = I, each cube's eight corners cospherical: every tetrahedron's search meets exact
//    ties, which the interval filter cannot decide (the worst case of the exact path);
//  - "decimal": "delaunay" scaled by 1/10 (its metric by 100: the same lengths), as an ASCII file
//    writes it: coordinates that are not doubles, so the checks take their interval paths instead
//    of the static filters that a binary file's doubles allow.
// Each on one thread (CPU time), and "all checks" also on two (`/2`, wall-clock time: the locally
// uniform search and the sliver measure run per tetrahedron and per face pair on every thread).
// Run: build/bin/certifier3_bench (figures in docs/bench.md).
#include "geometry/kuhn_grid.hpp"
#include "io/formats/medit.hpp"
#include "oracle/certify/mesh_certifier3.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

using anisocert::Rational;
using anisocert::predicates::Sym3;
using namespace anisocert::oracle;

namespace {

enum class Grid { delaunay, ties, decimal };

anisocert::geometry::Mesh3<Rational> grid(int n, Grid kind) {
  auto m = anisocert::geometry::kuhn_grid(n);
  const Rational a = kind == Grid::ties ? Rational(0) : Rational(-1, 4);
  m.metrics.assign(m.vertices.size(), Sym3<Rational>{1, a, a, 1, a, 1});
  if (kind == Grid::decimal) {  // the same mesh in tenths (an ASCII file's decimals: not doubles), M × 100
    for (auto& p : m.vertices) p = {p.x / 10, p.y / 10, p.z / 10};
    for (auto& M : m.metrics) M = {100 * M.m11, 100 * M.m12, 100 * M.m13, 100 * M.m22, 100 * M.m23, 100 * M.m33};
  }
  return m;
}

void counters(benchmark::State& state, std::size_t tetrahedra) {
  state.counters["tetrahedra_per_s"] = benchmark::Counter(static_cast<double>(tetrahedra), benchmark::Counter::kIsIterationInvariantRate);
}

void valid(benchmark::State& state) {
  const auto m = grid(static_cast<int>(state.range(0)), Grid::delaunay);
  Certify3Options o;
  o.uniform = false;
  o.threads = 1;
  Certify3Report r;
  for (auto _ : state) r = certify_mesh3(m, o);
  if (!r.valid_holds()) state.SkipWithError("the Kuhn grid is not valid");
  counters(state, m.tetrahedra.size());
}

void all_checks(benchmark::State& state, Grid kind) {
  const auto m = grid(static_cast<int>(state.range(0)), kind);
  Certify3Options o;
  o.metric = true;
  o.threads = static_cast<int>(state.range(1));
  Certify3Report r;
  for (auto _ : state) r = certify_mesh3(m, o);
  if (!r.valid_holds() || !r.uniform_violations.empty()) state.SkipWithError("the Kuhn grid does not hold");
  if (kind != Grid::ties && !r.uniform_ties.empty()) state.SkipWithError("the Kuhn grid has ties for the Delaunay metric");
  counters(state, m.tetrahedra.size());
}

// The two costly checks apart: local uniformity alone, edge lengths alone (validity off).
void one_check(benchmark::State& state, bool uniform) {
  const auto m = grid(static_cast<int>(state.range(0)), Grid::delaunay);
  Certify3Options o;
  o.valid = false;
  o.uniform = uniform;
  o.metric = !uniform;
  o.threads = 1;
  Certify3Report r;
  for (auto _ : state) r = certify_mesh3(m, o);
  counters(state, m.tetrahedra.size());
  if (uniform) state.counters["insphere_tests_per_tetrahedron"] = static_cast<double>(r.insphere_tests) / static_cast<double>(m.tetrahedra.size());
}

// A bad mesh of about a million tetrahedra (n = 55: 998,250), issue 39's bounded cost: the Kuhn grid
// under M with off-diagonals +¼ (the main diagonal lengthened), for which many tetrahedra have a vertex inside their M-sphere (each
// one witness), with every check and bound (ρ₀ = 2, γ₀ = 2, quality 0.5, angles 30°); witnesses
// counted in full, the first 100 of each list described; the peak resident memory is reported.
void bad_million(benchmark::State& state) {
  auto m = anisocert::geometry::kuhn_grid(static_cast<int>(state.range(0)));
  m.metrics.assign(m.vertices.size(), Sym3<Rational>{1, Rational(1, 4), Rational(1, 4), 1, Rational(1, 4), 1});
  Certify3Options o;
  o.metric = true, o.rho0 = 2, o.gamma0 = 2, o.min_quality = Rational(1, 2), o.min_angle = 30;
  o.threads = static_cast<int>(state.range(1));
  Certify3Report r;
  for (auto _ : state) r = certify_mesh3(m, o);
  if (r.uniform_violations.count() == 0) state.SkipWithError("the stretched Kuhn grid should fail local uniformity");
  counters(state, m.tetrahedra.size());
  state.counters["uniform_violations"] = static_cast<double>(r.uniform_violations.count());

  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  state.counters["peak_rss_MB"] = static_cast<double>(u.ru_maxrss) / 1024;
}

// Reading the Medit text of the same mesh (ASCII), for scale.
void read_medit(benchmark::State& state) {
  anisocert::io::MeshFile f;
  f.dimension = 3;
  f.mesh3 = grid(static_cast<int>(state.range(0)), Grid::delaunay);
  f.mesh3.metrics.clear();
  const std::string text = anisocert::io::medit_mesh_text(f);
  for (auto _ : state) benchmark::DoNotOptimize(anisocert::io::read_medit(text, "grid.mesh"));
  counters(state, f.mesh3.tetrahedra.size());
}

}  // namespace

BENCHMARK(valid)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(all_checks, delaunay, Grid::delaunay)->Args({10, 1})->Args({30, 1})->Args({30, 2})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(all_checks, decimal, Grid::decimal)->Args({30, 1})->Args({30, 2})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(all_checks, ties, Grid::ties)->Args({10, 1})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(one_check, uniform, true)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(one_check, lengths, false)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(read_medit)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(bad_million)->Args({55, 2})->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
