// The LS refiner with M ≡ I against CGAL's Delaunay_mesher_2 (issue 16's sanity anchor: with one
// isotropic metric, LS Voronoi refinement is Ruppert's algorithm). Same domains, same smallest
// angle θ = 20° (CGAL's shape bound b = sin²θ: Delaunay_mesh_criteria_2 compares sin² of the
// smallest angle with b), same size rule (circumradius at most `size`, a CGAL criteria class
// below, since CGAL's own size criterion bounds edge lengths), side by side in one run.
// Counters: vertices, triangles, smallest angle (degrees, doubles: a report, not a verdict; the
// exact checks are the tests'), vertices per second.
// What differs, by design: CGAL refines a constrained Delaunay triangulation (LS: the Voronoi
// diagram's dual, subsegments split while any cell but their endpoints' meets them), splits
// encroached subsegments at midpoints with clusters at small input angles (LS: in the
// encroacher's cell, nearest the midpoint), and refines the worst triangle first (LS: first in,
// first out). Run: build/bin/ls_cgal_bench (figures in docs/bench.md).
#include "fields/registry.hpp"
#include "refiners/ls/ls_refiner.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Point = K::Point_2;
using Polygon = std::vector<anisocert::predicates::Point2<double>>;

// CGAL's shape criterion and LS's size rule: bad when sin² of the smallest angle is below b, or
// (first) when the circumradius exceeds `size` (0: none).
class Criteria : public virtual CGAL::Delaunay_mesh_criteria_2<CDT> {
 public:
  using Base = CGAL::Delaunay_mesh_criteria_2<CDT>;
  Criteria(double b, double size) : Base(b), size_(size) {}
  struct Quality : std::pair<double, double> {  // sine², circumradius² / size²
    Quality() = default;
    Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
    bool operator<(const Quality& q) const {  // q1 < q2: q1 first
      if (second > 1 || q.second > 1) return second > q.second;
      return first < q.first;
    }
  };
  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(double b, double size, const K& traits) : Base::Is_bad(b, traits), size2_(size * size) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
      if (q.second > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.first < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const CDT::Face_handle& f, Quality& q) const {
      double sine = 0;
      Base::Is_bad::operator()(f, sine);
      const double r2 = CGAL::squared_radius(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      q = Quality(sine, size2_ > 0 ? r2 / size2_ : 0);
      return operator()(q);
    }

   private:
    double size2_;
  };
  Is_bad is_bad_object() const { return Is_bad(bound(), size_, traits); }

 private:
  double size_;
};

// Each with a point inside it: CGAL's seed (seeds_are_in_domain), so that only Ω is meshed.
struct TestDomain {
  const char* name;
  Polygon corners;
  Point seed;
};
const std::vector<TestDomain> kDomains = {
    {"square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0.5, 0.5}},
    {"L", {{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}}, {0.25, 0.25}},
    {"pentagon", {{0, 0}, {2, 0}, {2.5, 1}, {1, 1.75}, {-0.5, 1}}, {1, 1}},
    {"octagon", {{1, -0.375}, {1, 0.375}, {0.375, 1}, {-0.375, 1}, {-1, 0.375}, {-1, -0.375}, {-0.375, -1}, {0.375, -1}}, {0, 0}},
    {"comb",
     {{0, 0}, {1, 0}, {1, 1}, {0.75, 1}, {0.75, 0.25}, {0.5, 0.25}, {0.5, 1}, {0.25, 1}, {0.25, 0.25}, {0.125, 0.25}, {0.125, 1}, {0, 1}},
     {0.5, 0.125}},
};
constexpr double kTheta = 20;

double smallest_angle(const Point& a, const Point& b, const Point& c) {
  const auto angle = [](const Point& p, const Point& q, const Point& r) {  // at q
    const double ux = p.x() - q.x(), uy = p.y() - q.y(), wx = r.x() - q.x(), wy = r.y() - q.y();
    return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / M_PI;
  };
  return std::min({angle(c, a, b), angle(a, b, c), angle(b, c, a)});
}

void counters(benchmark::State& state, std::size_t vertices, std::size_t triangles, double angle, double seconds) {
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["min_angle_deg"] = angle;
  state.counters["vertices_per_s"] = static_cast<double>(vertices) / seconds;
}

void ls(benchmark::State& state, int domain, double size) {
  anisocert::refiners::ls::LsParameters p;
  p.theta_bound = kTheta, p.size = size, p.max_vertices = 2000000, p.max_seconds = 600;
  const auto field = anisocert::fields::make_field("constant", {{"m11", 1}, {"m12", 0}, {"m22", 1}});
  const anisocert::refiners::common::Domain d(kDomains[domain].corners);
  anisocert::refiners::ls::LsResult r;
  for (auto _ : state) r = anisocert::refiners::ls::refine_ls(d, field, p);
  double angle = 180;
  for (const auto& t : r.mesh.triangles) {
    const auto& s = r.mesh.sites;
    angle = std::min(angle, smallest_angle({s[t[0]].x, s[t[0]].y}, {s[t[1]].x, s[t[1]].y}, {s[t[2]].x, s[t[2]].y}));
  }
  counters(state, r.mesh.sites.size(), r.mesh.triangles.size(), angle, r.seconds);
  state.counters["finished"] = r.consistent;
}

void cgal(benchmark::State& state, int domain, double size) {
  const double b = std::pow(std::sin(kTheta * M_PI / 180), 2);
  std::size_t vertices = 0, triangles = 0;
  double angle = 180, seconds = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    CDT cdt;
    const Polygon& p = kDomains[domain].corners;
    for (std::size_t k = 0; k < p.size(); ++k)
      cdt.insert_constraint(Point(p[k].x, p[k].y), Point(p[(k + 1) % p.size()].x, p[(k + 1) % p.size()].y));
    const std::vector<Point> seeds{kDomains[domain].seed};
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), Criteria(b, size), true);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    vertices = cdt.number_of_vertices(), triangles = 0, angle = 180;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!f->is_in_domain()) continue;
      ++triangles;
      angle = std::min(angle, smallest_angle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    }
  }
  counters(state, vertices, triangles, angle, seconds);
}

void both(int domain, double size, const std::string& label) {
  const std::string name = std::string(kDomains[domain].name) + "/size_" + label;
  benchmark::RegisterBenchmark(("ls/" + name).c_str(), ls, domain, size)->Iterations(1)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("cgal/" + name).c_str(), cgal, domain, size)->Iterations(1)->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  for (int d = 0; d < static_cast<int>(kDomains.size()); ++d) {
    both(d, 0, "none");
    both(d, 0.02, "0.02");
    both(d, 0.004, "0.004");
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
