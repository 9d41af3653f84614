// Reading and certifying a mesh from another mesher (issue 12 targets: at least 20 MB/s reading an
// ASCII Medit mesh, and at least 1M triangles per second for each of the validity and metric
// conformity checks, on a mesh of about 1M triangles, with exact answers). The enclosures all
// checks share are measured apart (Enclose): a certification pays them once. The mesh: a k×k grid of
// the unit square with decimal coordinates of 6 digits (i/k written as the rounded decimal
// the way meshers print them, so every coordinate is a decimal rational, not a double), each cell
// split along a diagonal, the metric M = diag(k², 4k²)-ish per vertex as decimal text; written
// once by the project's Medit writer, then read back as a user's file.
// Run: build/bin/mesh_file_bench (figures in docs/bench.md).
#include "io/formats/medit.hpp"
#include "oracle/certify/metric_checks.hpp"
#include "oracle/certify/triangulation_check.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>

using namespace anisocert;

namespace {

struct Fixture {
  std::string mesh_text, sol_text;
  io::MeshFile file;
};

// k = 708 gives 2·708² ≈ 1.0M triangles.
const Fixture& fixture() {
  static const Fixture f = [] {
    const int k = 708;
    io::MeshFile m;
    auto decimal = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.6f", v);
      return parse_rational(buf);
    };
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= k; ++i) {
        m.mesh.sites.push_back({decimal(static_cast<double>(i) / k), decimal(static_cast<double>(j) / k)});
        m.mesh.metrics.push_back({decimal(k * k * (1 + 0.5 * i / k)), decimal(0.1 * k * k), decimal(k * k * 1.5)});
      }
    auto at = [&](int i, int j) { return j * (k + 1) + i; };
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) {
        m.mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        m.mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    for (int i = 0; i < k; ++i) {
      m.mesh.edges.push_back({at(i, 0), at(i + 1, 0)});
      m.mesh.edges.push_back({at(k, i), at(k, i + 1)});
      m.mesh.edges.push_back({at(i + 1, k), at(i, k)});
      m.mesh.edges.push_back({at(0, i + 1), at(0, i)});
    }
    Fixture fx;
    fx.mesh_text = io::medit_mesh_text(m);
    fx.sol_text = io::medit_sol_text(m.mesh.metrics);
    fx.file = io::read_medit(fx.mesh_text, "bench.mesh");
    fx.file.mesh.metrics = io::read_medit_sol(fx.sol_text, "bench.sol");
    return fx;
  }();
  return f;
}

void ReadMeditAscii(benchmark::State& state) {
  const Fixture& f = fixture();
  for (auto _ : state) {
    io::MeshFile m = io::read_medit(f.mesh_text, "bench.mesh");
    m.mesh.metrics = io::read_medit_sol(f.sol_text, "bench.sol");
    benchmark::DoNotOptimize(m);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * (f.mesh_text.size() + f.sol_text.size())));
  state.counters["MB"] = static_cast<double>(f.mesh_text.size() + f.sol_text.size()) / 1e6;
}

// The enclosures of every coordinate and metric entry, computed once per certification and shared
// by every check (oracle::EnclosedMesh).
void Enclose(benchmark::State& state) {
  const Fixture& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(oracle::EnclosedMesh(f.file.mesh));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.file.mesh.triangles.size()));
}

void Validity(benchmark::State& state) {
  const Fixture& f = fixture();
  const oracle::EnclosedMesh m(f.file.mesh);
  for (auto _ : state) {
    const oracle::TriangulationCheck t = oracle::check_triangulation(m, oracle::triangle_cells(f.file.mesh.triangles));
    if (!t.is_triangulation) state.SkipWithError("the grid is not valid");
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.file.mesh.triangles.size()));
}

void Conformity(benchmark::State& state) {
  const Fixture& f = fixture();
  const oracle::EnclosedMesh m(f.file.mesh);
  for (auto _ : state) {
    const auto edges = oracle::unique_edges(oracle::triangle_cells(f.file.mesh.triangles), f.file.mesh.sites.size());
    benchmark::DoNotOptimize(oracle::check_lengths(m, edges, std::nullopt));
    benchmark::DoNotOptimize(oracle::check_quality(m, std::nullopt));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.file.mesh.triangles.size()));
}

}  // namespace

BENCHMARK(ReadMeditAscii)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(Enclose)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(Validity)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(Conformity)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
