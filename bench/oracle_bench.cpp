// The oracle's costs: enumerating the real common points of two conics, and the sign of a
// polynomial at such a point through the fast path (interval value on the isolating interval)
// and through the exact path (the gcd zero test, for a polynomial that vanishes there).
// Run: build/bin/oracle_bench (figures in docs/bench.md).

#include "oracle/algebraic/conic_intersection.hpp"

#include <benchmark/benchmark.h>

using anisocert::Rational;
using namespace anisocert::oracle;

namespace {

// x² + 4y² = 4 and x² − y² = 1: four points of degree 2 coordinates.
const Conic A{1, 0, 4, 0, 0, -4}, B{1, 0, -1, 0, 0, -1};
// Two generic conics through the four points (±1, ±1)·(1, 2) and a fifth: degree-4 vertices.
const Conic C{Rational(3, 2), Rational(1, 3), 1, Rational(-1, 2), Rational(2, 5), -3};
const Conic D{1, Rational(-2, 7), Rational(5, 3), Rational(1, 4), -1, Rational(-7, 3)};

void enumerate(benchmark::State& state, const Conic& P, const Conic& Q) {
  for (auto _ : state) benchmark::DoNotOptimize(intersect(P, Q).points.size());
}

// Sign of x − y (never zero at these points): decided by the fast path.
void sign_fast(benchmark::State& state, const Conic& P, const Conic& Q) {
  Bivariate f;
  f.add(1, 0, 1).add(0, 1, -1).add(0, 0, Rational(1, 3));
  for (auto _ : state) {
    state.PauseTiming();
    auto r = intersect(P, Q);  // a fresh point each time: no refinement cached from earlier calls
    state.ResumeTiming();
    benchmark::DoNotOptimize(r.points.front().point.sign_of(f));
  }
}

// Sign of P + 2Q (zero at every common point): needs the exact zero test.
void sign_exact(benchmark::State& state, const Conic& P, const Conic& Q) {
  Bivariate f = P.polynomial();
  for (const auto& [ij, c] : Q.polynomial().terms) f.add(ij.first, ij.second, 2 * c);
  for (auto _ : state) {
    state.PauseTiming();
    auto r = intersect(P, Q);
    state.ResumeTiming();
    benchmark::DoNotOptimize(r.points.front().point.sign_of(f));
  }
}

BENCHMARK_CAPTURE(enumerate, degree2_points, A, B);
BENCHMARK_CAPTURE(enumerate, generic_pair, C, D);
BENCHMARK_CAPTURE(sign_fast, degree2_points, A, B);
BENCHMARK_CAPTURE(sign_fast, generic_pair, C, D);
BENCHMARK_CAPTURE(sign_exact, degree2_points, A, B);
BENCHMARK_CAPTURE(sign_exact, generic_pair, C, D);

}  // namespace

BENCHMARK_MAIN();
