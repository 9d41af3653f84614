// The exact diagram's cost and how it grows. Issue 5 targets (exact constructions): n = 200 in
// under 5 s, n = 1000 in under 60 s, memory under 2 GB. Issue 14 targets (filtered constructions):
// n = 1000 in at most 1.5 s on one thread, and the vertices within 5× of a plain floating-point
// computation of the same vertices. Inputs: uniformly random sites in the unit square with metrics
// whose eigen-directions turn with x and whose anisotropy (ratio of unit-ball axes) varies
// smoothly from 1:1 to 10:1 with y. Each phase's time is a counter (seconds), side by side:
//   diagram/N/THREADS          filtered constructions (the default)
//   diagram_exact_only/N       every point built exactly (--exact-only), one thread
//   vertices_float/N/SIDE      the baseline: for every candidate triple, Newton's method in
//                              doubles on the two bisectors from SIDE × SIDE starts spread over the
//                              triple's region, and the nearest sites at each root found in doubles
//                              (no certification). One start finds about 70% of the diagram's
//                              vertices (counter voronoi_nodes of diagram/N); 3 × 3 starts about
//                              98–99.6%, the least that computes nearly the same vertices
//   vertices_certified/N       the same with the filtered path's isolation: every common point in
//                              the triple's region, certified in intervals (certified_roots.hpp),
//                              and the nearest sites in intervals (no exact fallback, no nodes)
// Run: build/bin/diagram_bench (figures in docs/bench.md); peak memory: /usr/bin/time -v.
#include "oracle/algebraic/certified_roots.hpp"
#include "oracle/diagram/candidate_subdivision.hpp"
#include "oracle/diagram/diagram.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <optional>
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

void report(benchmark::State& state, const Diagram& d) {
  state.counters["candidates_s"] = d.stats.seconds_candidates;
  state.counters["vertices_s"] = d.stats.seconds_vertices;
  state.counters["arcs_s"] = d.stats.seconds_arcs;
  state.counters["faces_s"] = d.stats.seconds_faces;
  state.counters["dual_s"] = d.stats.seconds_dual;
  state.counters["triples"] = static_cast<double>(d.stats.triples);
  state.counters["pairs"] = static_cast<double>(d.stats.pairs);
  state.counters["nodes"] = static_cast<double>(d.nodes.size());
  state.counters["voronoi_nodes"] = static_cast<double>(
      std::count_if(d.nodes.begin(), d.nodes.end(), [](const Node& v) { return v.kind == Node::Kind::voronoi; }));
  state.counters["arcs"] = static_cast<double>(d.arcs.size());
  state.counters["exact_roots"] = static_cast<double>(d.stats.filters.roots_exact);
  state.counters["exact_points"] = static_cast<double>(d.stats.filters.exact_points);
}

void diagram(benchmark::State& state) {
  const Mesh<Rational> in = random_input(static_cast<int>(state.range(0)), 2026);
  DiagramOptions o;
  o.threads = static_cast<int>(state.range(1));
  Diagram d;
  for (auto _ : state) d = compute_diagram(in, o);
  report(state, d);
}

void diagram_exact_only(benchmark::State& state) {
  const Mesh<Rational> in = random_input(static_cast<int>(state.range(0)), 2026);
  DiagramOptions o;
  o.threads = 1, o.exact_only = true;
  Diagram d;
  for (auto _ : state) d = compute_diagram(in, o);
  report(state, d);
}

// A conic in doubles: a x² + b xy + c y² + d x + e y + f.
struct Quadric {
  double a, b, c, d, e, f;
  double at(double x, double y) const { return a * x * x + b * x * y + c * y * y + d * x + e * y + f; }
};

Quadric distance_of(const Mesh<Rational>& in, int v) {
  const double x = in.sites[v].x.convert_to<double>(), y = in.sites[v].y.convert_to<double>();
  const double m11 = in.metrics[v].m11.convert_to<double>(), m12 = in.metrics[v].m12.convert_to<double>(),
               m22 = in.metrics[v].m22.convert_to<double>();
  return {m11, 2 * m12, m22, -2 * (m11 * x + m12 * y), -2 * (m12 * x + m22 * y), m11 * x * x + 2 * m12 * x * y + m22 * y * y};
}

// Newton's method in doubles on A = B = 0 from (x, y), stopping as the certified path's Newton
// does (a step below about 5 ulps of the scale); the iterate if it converged inside the region.
std::optional<std::pair<double, double>> newton_in(const Quadric& A, const Quadric& B, double x, double y,
                                                   const BoxBounds& r) {
  for (int k = 0; k < 30; ++k) {
    const double fa = A.at(x, y), fb = B.at(x, y);
    const double a00 = 2 * A.a * x + A.b * y + A.d, a01 = A.b * x + 2 * A.c * y + A.e;
    const double a10 = 2 * B.a * x + B.b * y + B.d, a11 = B.b * x + 2 * B.c * y + B.e;
    const double det = a00 * a11 - a01 * a10;
    if (det == 0) return std::nullopt;
    const double sx = (a11 * fa - a01 * fb) / det, sy = (a00 * fb - a10 * fa) / det;
    x -= sx, y -= sy;
    if (std::abs(sx) <= 1e-15 * (std::abs(x) + r.x_hi - r.x_lo) && std::abs(sy) <= 1e-15 * (std::abs(y) + r.y_hi - r.y_lo)) {
      if (x < r.x_lo || x > r.x_hi || y < r.y_lo || y > r.y_hi) return std::nullopt;
      return std::pair{x, y};
    }
  }
  return std::nullopt;
}

void vertices_float(benchmark::State& state) {
  const Mesh<Rational> in = random_input(static_cast<int>(state.range(0)), 2026);
  const int side = static_cast<int>(state.range(1));
  const CandidateSets cand = candidate_sets(in);
  std::vector<Quadric> q;
  for (int v = 0; v < static_cast<int>(in.sites.size()); ++v) q.push_back(distance_of(in, v));
  const auto minus = [](const Quadric& p, const Quadric& s) {
    return Quadric{p.a - s.a, p.b - s.b, p.c - s.c, p.d - s.d, p.e - s.e, p.f - s.f};
  };
  std::size_t found = 0;
  for (auto _ : state) {
    found = 0;
    for (std::size_t i = 0; i < cand.triples.size(); ++i) {
      const auto& t = cand.triples[i];
      const BoxBounds& r = cand.triple_region[i];
      const Quadric A = minus(q[t[0]], q[t[1]]), B = minus(q[t[0]], q[t[2]]);
      std::vector<std::pair<double, double>> roots;
      for (int s = 0; s < side * side; ++s) {
        const double x0 = r.x_lo + (r.x_hi - r.x_lo) * (s % side + 0.5) / side;
        const double y0 = r.y_lo + (r.y_hi - r.y_lo) * (s / side + 0.5) / side;
        const auto z = newton_in(A, B, x0, y0, r);
        if (!z) continue;
        bool seen = false;
        for (const auto& [x, y] : roots) seen = seen || std::abs(x - z->first) + std::abs(y - z->second) < 1e-9;
        if (seen) continue;
        roots.push_back(*z);
        const auto [x, y] = *z;
        const double qa = q[t[0]].at(x, y);
        bool closer = false;
        for (int u : cand.sites_near({x, x}, {y, y}))
          closer = closer || (u != t[0] && u != t[1] && u != t[2] && q[u].at(x, y) < qa * (1 - 1e-9));
        found += closer ? 0 : 1;
      }
    }
    benchmark::DoNotOptimize(found);
  }
  state.counters["vertices"] = static_cast<double>(found);
  state.counters["triples"] = static_cast<double>(cand.triples.size());
}

// Q_v in intervals, from the exact site and metric.
IntervalConic distance_enclosure(const Mesh<Rational>& in, int v) {
  using anisocert::FilterInterval;
  const FilterInterval x = FilterInterval::around(in.sites[v].x), y = FilterInterval::around(in.sites[v].y);
  const FilterInterval m11 = FilterInterval::around(in.metrics[v].m11), m12 = FilterInterval::around(in.metrics[v].m12),
                       m22 = FilterInterval::around(in.metrics[v].m22), two(2);
  return {m11, two * m12, m22, FilterInterval(-2) * (m11 * x + m12 * y), FilterInterval(-2) * (m12 * x + m22 * y),
          m11 * x * x + two * m12 * x * y + m22 * y * y};
}

void vertices_certified(benchmark::State& state) {
  using anisocert::FilterInterval;
  const Mesh<Rational> in = random_input(static_cast<int>(state.range(0)), 2026);
  const CandidateSets cand = candidate_sets(in);
  std::vector<IntervalConic> q;
  for (int v = 0; v < static_cast<int>(in.sites.size()); ++v) q.push_back(distance_enclosure(in, v));
  const auto minus = [](const IntervalConic& p, const IntervalConic& s) {
    return IntervalConic{p.a - s.a, p.b - s.b, p.c - s.c, p.d - s.d, p.e - s.e, p.f - s.f};
  };
  const auto value = [](const IntervalConic& g, const FilterInterval& x, const FilterInterval& y) {
    return g.a * x * x + g.b * x * y + g.c * y * y + g.d * x + g.e * y + g.f;
  };
  std::size_t found = 0, undecided = 0;
  for (auto _ : state) {
    found = undecided = 0;
    for (std::size_t i = 0; i < cand.triples.size(); ++i) {
      const auto& t = cand.triples[i];
      const auto& r = cand.triple_region[i];
      const auto roots = certified_common_roots(minus(q[t[0]], q[t[1]]), minus(q[t[0]], q[t[2]]),
                                                {{r.x_lo, r.x_hi}, {r.y_lo, r.y_hi}});
      if (!roots) {
        ++undecided;
        continue;
      }
      for (const IntervalBox& b : *roots) {
        const FilterInterval qa = value(q[t[0]], b.x, b.y);
        bool closer = false;
        for (int u : cand.sites_near(b.x, b.y)) closer = closer || value(q[u], b.x, b.y).hi < qa.lo;
        found += closer ? 0 : 1;
      }
    }
    benchmark::DoNotOptimize(found);
  }
  state.counters["points"] = static_cast<double>(found);
  state.counters["undecided_triples"] = static_cast<double>(undecided);
  state.counters["triples"] = static_cast<double>(cand.triples.size());
}

}  // namespace

BENCHMARK(diagram)->ArgsProduct({{200, 1000, 4000, 16000}, {1, 2}})->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK(diagram_exact_only)->Arg(200)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(vertices_float)->ArgsProduct({{200, 1000, 4000, 16000}, {1, 3}})->Unit(benchmark::kMillisecond);
BENCHMARK(vertices_certified)->Arg(200)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
