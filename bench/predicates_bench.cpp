// Per predicate: plain double evaluation vs filtered vs exact, on random inputs and on
// near-degenerate ones (one coordinate moved to within a few ulps of where the exact sign
// changes), with the share of filtered calls that reached the interval and exact stages.
// Run: build/bin/predicates_bench (see docs/bench.md).

#include "predicates/angle.hpp"
#include "predicates/bisector.hpp"
#include "predicates/distortion.hpp"
#include "predicates/incircle.hpp"
#include "predicates/length_compare.hpp"
#include "predicates/metric_dot.hpp"
#include "predicates/orientation.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::Sign;

namespace {

constexpr std::size_t batch = 1024;

template <class K>
std::array<double, K::arity> random_input(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.1, 1);
  std::array<double, K::arity> x{};
  for (std::size_t i = 0; i < K::arity; ++i) x[i] = K::groups[i] == 2 ? pos(rng) : u(rng);
  for (std::size_t i = 0; i + 2 < K::arity; ++i)  // metric triples: positive definite
    if (K::groups[i] == 1 && K::groups[i + 1] == 1 && K::groups[i + 2] == 1) {
      x[i] = pos(rng), x[i + 2] = pos(rng), x[i + 1] = 0.9 * u(rng) * std::sqrt(x[i] * x[i + 2]);
      i += 2;
    }
  return x;
}

template <class K>
Sign exact_at(std::array<double, K::arity> x) {
  std::array<Rational, K::arity> q;
  for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
  return exact_sign<K>(q);
}

// Moves input 0 (a coordinate in every kernel) by bisection to the double where the exact
// sign changes, then a few ulps off it. Nothing when input 0 does not change the sign in ±2.
template <class K>
std::optional<std::array<double, K::arity>> near_degenerate(std::array<double, K::arity> x, std::mt19937_64& rng) {
  double lo = x[0] - 2, hi = x[0] + 2;
  x[0] = lo;
  const Sign s_lo = exact_at<K>(x);
  x[0] = hi;
  if (exact_at<K>(x) == s_lo || s_lo == Sign::zero) return std::nullopt;
  while (true) {
    const double mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;
    x[0] = mid;
    (exact_at<K>(x) == s_lo ? lo : hi) = mid;
  }
  x[0] = lo;
  for (int k = std::uniform_int_distribution<int>(0, 3)(rng); k > 0; --k) x[0] = std::nextafter(x[0], -INFINITY);
  return x;
}

template <class K, bool near>
const std::vector<std::array<double, K::arity>>& inputs() {
  static const auto data = [] {
    std::mt19937_64 rng(near ? 2 : 1);
    std::vector<std::array<double, K::arity>> v;
    while (v.size() < batch) {
      auto x = random_input<K>(rng);
      if (!near) {
        v.push_back(x);
      } else if (auto d = near_degenerate<K>(x, rng)) {
        v.push_back(*d);
      }
    }
    return v;
  }();
  return data;
}

template <class K, bool near>
void plain_double(benchmark::State& state) {
  const auto& in = inputs<K, near>();
  std::size_t i = 0;
  for (auto _ : state) {
    const double v = K::template eval<double>(in[i++ % batch]);
    benchmark::DoNotOptimize(v > 0 ? 1 : v < 0 ? -1 : 0);
  }
}

template <class K, bool near>
void filtered(benchmark::State& state) {
  const auto& in = inputs<K, near>();
  filter_stats() = {};
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(filtered_sign<K>(in[i++ % batch]));
  const FilterStats& s = filter_stats();
  state.counters["interval_share"] = double(s.interval_stage) / double(i);
  state.counters["exact_share"] = double(s.exact_stage) / double(i);
}

template <class K, bool near>
void exact(benchmark::State& state) {
  const auto& in = inputs<K, near>();
  std::vector<std::array<Rational, K::arity>> q(batch);
  for (std::size_t j = 0; j < batch; ++j)
    for (std::size_t k = 0; k < K::arity; ++k) q[j][k] = Rational(in[j][k]);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(exact_sign<K>(q[i++ % batch]));
}

#define ANISOCERT_BENCH(K)                                  \
  BENCHMARK(plain_double<K, false>)->Name(#K "/random/double");   \
  BENCHMARK(filtered<K, false>)->Name(#K "/random/filtered");     \
  BENCHMARK(exact<K, false>)->Name(#K "/random/exact");           \
  BENCHMARK(plain_double<K, true>)->Name(#K "/near/double");      \
  BENCHMARK(filtered<K, true>)->Name(#K "/near/filtered");        \
  BENCHMARK(exact<K, true>)->Name(#K "/near/exact");

ANISOCERT_BENCH(OrientationKernel)
ANISOCERT_BENCH(SideOfBisectorKernel)
ANISOCERT_BENCH(MetricDotKernel)
ANISOCERT_BENCH(InCircleKernel)
ANISOCERT_BENCH(ScaledLengthCompareKernel)
ANISOCERT_BENCH(AngleCosKernel)
ANISOCERT_BENCH(ScaledDifferenceDeterminantKernel)

}  // namespace

BENCHMARK_MAIN();
