// The mesh certifier's throughput (issue 6 target: at least 200k triangles per second for the
// locally uniform check; issue 14: with 1 and 2 threads, the second argument, in wall-clock time). Meshes: a jittered k×k lattice, boundary points left on ∂Ω, each cell
// split by its Delaunay diagonal for the metric (locally Delaunay, hence Delaunay), so every
// check holds and runs to the end; "isotropic" with M = I, "anisotropic" with M = diag(16, 1) on
// a lattice 4 times finer in x (the same mesh seen through the metric).
// Run: build/bin/certifier_bench (figures in docs/bench.md).
#include "oracle/certify/mesh_certifier.hpp"
#include "predicates/incircle.hpp"

#include <benchmark/benchmark.h>

#include <random>

using anisocert::Rational;
using namespace anisocert::oracle;
using anisocert::predicates::Point2;
using anisocert::predicates::Sym2;

namespace {

Mesh<Rational> lattice(int k, bool anisotropic) {
  Mesh<Rational> m;
  const double sx = anisotropic ? 0.25 : 1.0;
  const Sym2<Rational> M = anisotropic ? Sym2<Rational>{16, 0, 1} : Sym2<Rational>{1, 0, 1};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const bool boundary = i == 0 || j == 0 || i == k || j == k;
      const double x = (i + (boundary ? 0 : jitter(rng))) * sx, y = j + (boundary ? 0 : jitter(rng));
      m.sites.push_back({Rational(x), Rational(y)});
    }
  m.metrics.assign(m.sites.size(), M);
  const Sym2<double> Md{M.m11.convert_to<double>(), M.m12.convert_to<double>(), M.m22.convert_to<double>()};
  auto at = [&](int i, int j) { return j * (k + 1) + i; };
  auto pd = [&](int v) { return Point2<double>{m.sites[v].x.convert_to<double>(), m.sites[v].y.convert_to<double>()}; };
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      // Diagonal ac unless d is inside the circumellipse of abc.
      if (anisocert::predicates::incircle(pd(a), pd(b), pd(c), pd(d), Md) > anisocert::Sign::zero)
        m.triangles.push_back({a, b, d}), m.triangles.push_back({b, c, d});
      else
        m.triangles.push_back({a, b, c}), m.triangles.push_back({a, c, d});
    }
  m.domain = {{0, 0}, {Rational(k * sx), 0}, {Rational(k * sx), k}, {0, k}};
  return m;
}

void uniform(benchmark::State& state, bool anisotropic) {
  const Mesh<Rational> m = lattice(static_cast<int>(state.range(0)), anisotropic);
  CertifyOptions o;
  o.valid = false;
  o.threads = static_cast<int>(state.range(1));
  CertifyReport r;
  for (auto _ : state) r = certify_mesh(m, o);
  if (!r.uniform_violations.empty()) state.SkipWithError("the lattice mesh is not locally uniform");
  state.counters["triangles_per_s"] = benchmark::Counter(static_cast<double>(m.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["incircle_tests_per_triangle"] = static_cast<double>(r.incircle_tests) / m.triangles.size();
}

void valid(benchmark::State& state) {
  const Mesh<Rational> m = lattice(static_cast<int>(state.range(0)), false);
  CertifyOptions o;
  o.uniform = false;
  CertifyReport r;
  for (auto _ : state) r = certify_mesh(m, o);
  if (!r.valid_holds()) state.SkipWithError("the lattice mesh is not valid");
  state.counters["triangles_per_s"] = benchmark::Counter(static_cast<double>(m.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK_CAPTURE(uniform, isotropic, false)->ArgsProduct({{100, 300}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniform, anisotropic, true)->ArgsProduct({{100, 300}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(valid)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
