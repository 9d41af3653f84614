#include "oracle/certify/mesh_certifier.hpp"

#include "geometry/circumellipse.hpp"
#include "geometry/distortion_estimate.hpp"
#include "geometry/ellipse_box.hpp"
#include "oracle/certify/site_tree.hpp"
#include "oracle/parallel_for.hpp"
#include "predicates/distortion.hpp"
#include "predicates/incircle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::oracle {

using predicates::Point2;
using predicates::Sym2;

namespace {

std::pair<int, int> ordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

constexpr double inf = std::numeric_limits<double>::infinity();

std::string name(const char* what, int i) { return std::string(what) + " " + std::to_string(i); }

// sign of the in-circle test of site s against triangle t in the metric of vertex v (LU
// Definition 2.1): positive strictly inside the M_v-circumellipse.
Sign incircle(const EnclosedMesh& m, const std::array<int, 3>& t, int s, int v) {
  const auto &a = m.site[t[0]], &b = m.site[t[1]], &c = m.site[t[2]], &d = m.site[s];
  const auto& M = m.metric[v];
  return predicates::interval_then_exact<predicates::InCircleKernel>(
      std::array<FilterInterval, 11>{a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y, M.m11, M.m12, M.m22}, [&] {
        const auto& p = m.mesh.sites;
        const auto& n = m.mesh.metrics;
        return std::array<Rational, 11>{p[t[0]].x, p[t[0]].y, p[t[1]].x, p[t[1]].y, p[t[2]].x, p[t[2]].y,
                                        p[s].x,    p[s].y,    n[v].m11,  n[v].m12,  n[v].m22};
      });
}

// What the locally uniform check found at one triangle, in the order found.
struct UniformFinding {
  bool strict;
  int vertex, site;
};
struct UniformResult {
  bool unmeasured = false;
  std::size_t incircle_tests = 0;
  std::vector<UniformFinding> found;
};

// LU §3–§4: triangle t's circumellipse in each of its vertices' metrics is empty of sites. One
// witness per triangle: its search stops at the first site strictly inside.
UniformResult check_uniform_at(const EnclosedMesh& m, const SiteTree& tree, int t) {
  UniformResult r;
  const auto& tri = m.mesh.triangles[t];
  if (m.orientation(tri[0], tri[1], tri[2]) != Sign::positive) {  // `valid` reports it
    r.unmeasured = true;
    return r;
  }
  bool violated = false, tied = false;
  for (int i = 0; i < 3 && !violated; ++i) {
    const int v = tri[i];
    // A metric equal to an earlier vertex's (a constant field) asks the same question again.
    auto same = [&](int u) {
      const Sym2<Rational>& p = m.mesh.metrics[u];
      const Sym2<Rational>& q = m.mesh.metrics[v];
      return p.m11 == q.m11 && p.m12 == q.m12 && p.m22 == q.m22;
    };
    if ((i > 0 && same(tri[0])) || (i > 1 && same(tri[1]))) continue;
    // The M_v-circumellipse, enclosed (geometry/circumellipse.hpp), and the box of the M_v-ball
    // around it: the sites outside that box are outside the ellipse, the rest are decided by the
    // exact in-circle predicate.
    const Sym2<FilterInterval>& mi = m.metric[v];
    const geometry::Circumellipse<FilterInterval> c =
        geometry::circumellipse(m.site[tri[0]], m.site[tri[1]], m.site[tri[2]], mi);
    const geometry::HalfWidths<FilterInterval> h = geometry::ellipse_half_widths(mi, c.r2);
    const double hx = h.hx.hi, hy = h.hy.hi;
    const bool bounded = std::isfinite(c.cx.lo) && std::isfinite(c.cx.hi) && std::isfinite(c.cy.lo) &&
                         std::isfinite(c.cy.hi) && std::isfinite(hx) && std::isfinite(hy);
    const double qx0 = bounded ? c.cx.lo - hx : -inf, qx1 = bounded ? c.cx.hi + hx : inf;
    const double qy0 = bounded ? c.cy.lo - hy : -inf, qy1 = bounded ? c.cy.hi + hy : inf;
    tree.visit(qx0, qx1, qy0, qy1, [&](int s) {
      if (s == tri[0] || s == tri[1] || s == tri[2]) return true;
      ++r.incircle_tests;
      const Sign in = incircle(m, tri, s, v);
      if (in == Sign::negative || (in == Sign::zero && tied)) return true;
      const bool strict = in == Sign::positive;
      r.found.push_back({strict, v, s});
      (strict ? violated : tied) = true;
      return !strict;
    });
  }
  return r;
}

// The triangles on every core (independent), their findings added in triangle order
// (parallel_in_order): the report does not depend on the number of threads.
void check_uniform(const EnclosedMesh& m, const SiteTree& tree, int threads, CertifyReport& r) {
  const auto compute = [&](std::size_t t) { return check_uniform_at(m, tree, static_cast<int>(t)); };
  parallel_in_order(m.mesh.triangles.size(), thread_count(threads), compute, [&](std::size_t ti, const UniformResult& u) {
    const int t = static_cast<int>(ti);
    r.unmeasured += u.unmeasured ? 1 : 0;
    r.incircle_tests += u.incircle_tests;
    for (const UniformFinding& f : u.found)
      (f.strict ? r.uniform_violations : r.uniform_ties).add(f.vertex, t, f.site, [&] {
        return name("site", f.site) + (f.strict ? " is strictly inside" : " is exactly on") + " the circumellipse of " +
               name("triangle", t) + " in the metric of " + name("vertex", f.vertex);
      });
  });
}

// The segment parameter of p on [a, b] (exact), or nothing when p is off the line.
std::optional<Rational> parameter_on(const Point2<Rational>& a, const Point2<Rational>& b, const Point2<Rational>& p) {
  if (predicates::orientation(a, b, p) != Sign::zero) return std::nullopt;
  const Rational len = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  return ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / len;
}

// Every constrained segment is a union of edges: the sites on it, in order, are joined by edges.
void check_segments(const EnclosedMesh& m, const SiteTree& tree, const std::vector<std::pair<int, int>>& edges,
                    std::size_t described, CertifyReport& r) {
  const auto& mesh = m.mesh;
  const auto fail = [&](auto text) {
    if (r.segment_failures.size() < described) r.segment_failures.push_back(text());
    ++r.segment_failure_count;
  };
  for (std::size_t k = 0; k < mesh.segments.size(); ++k) {
    const int a = mesh.segments[k].first, b = mesh.segments[k].second;
    if (mesh.sites[a].x == mesh.sites[b].x && mesh.sites[a].y == mesh.sites[b].y) {
      fail([&] {
        return "segment " + std::to_string(k) + " has length zero (sites " + std::to_string(a) + " and " + std::to_string(b) +
               "): it is no union of edges";
      });
      continue;
    }
    std::vector<std::pair<Rational, int>> on;
    const auto &pa = m.approx[a], &pb = m.approx[b];
    tree.visit(std::min(pa.x, pb.x), std::max(pa.x, pb.x), std::min(pa.y, pb.y), std::max(pa.y, pb.y), [&](int s) {
      if (const auto t = parameter_on(mesh.sites[a], mesh.sites[b], mesh.sites[s]); t && *t >= 0 && *t <= 1)
        on.emplace_back(*t, s);
    });
    std::sort(on.begin(), on.end());
    for (std::size_t i = 0; i + 1 < on.size(); ++i)
      if (!std::binary_search(edges.begin(), edges.end(), ordered(on[i].second, on[i + 1].second)))
        fail([&] {
          return "segment " + std::to_string(k) + " is not a union of edges: sites " + std::to_string(on[i].second) + " and " +
                 std::to_string(on[i + 1].second) + " are consecutive on it but not joined by an edge";
        });
  }
}

// The radius-edge ratio² of a triangle in metric M, r² / (shortest edge)², all measured by M, with r
// the M-radius of its circumellipse; over T = FilterInterval (an enclosure, to decide "≤ ρ₀²"
// without rationals when it is clear) and T = Rational (exact).
template <class T>
T radius_edge_squared(const std::array<Point2<T>, 3>& t, const Sym2<T>& M) {
  using std::min;
  auto q = [&](const T& dx, const T& dy) { return predicates::quadratic_form(M.m11, M.m12, M.m22, dx, dy); };
  const T e1 = q(t[1].x - t[0].x, t[1].y - t[0].y), e2 = q(t[2].x - t[0].x, t[2].y - t[0].y),
          e3 = q(t[2].x - t[1].x, t[2].y - t[1].y);
  return geometry::circumellipse(t[0], t[1], t[2], M).r2 / min(e1, min(e2, e3));
}

Sym2<double> nearest_doubles(const Sym2<Rational>& m) {
  return {m.m11.convert_to<double>(), m.m12.convert_to<double>(), m.m22.convert_to<double>()};
}

// ρ ≤ ρ₀ in every vertex's metric and τ ≤ γ₀ between the vertices of every triangle; one witness
// per triangle for each.
void check_quality_bounds(const EnclosedMesh& m, const CertifyOptions& o, CertifyReport& r) {
  const auto& mesh = m.mesh;
  const Rational rho2 = o.rho0 ? *o.rho0 * *o.rho0 : Rational(0), gamma2 = o.gamma0 ? *o.gamma0 * *o.gamma0 : Rational(0);
  const double rho2_lo = enclose(rho2).lo;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    if (m.orientation(tri[0], tri[1], tri[2]) == Sign::zero) continue;  // flat: `valid` reports it
    if (o.rho0)
      for (int v : tri) {
        const FilterInterval e = radius_edge_squared(std::array{m.site[tri[0]], m.site[tri[1]], m.site[tri[2]]}, m.metric[v]);
        if (e.hi < rho2_lo) {  // decided by the enclosure: ≤ ρ₀²
          const double approx = std::sqrt((e.lo + e.hi) / 2);
          if (approx > r.worst_rho) r.worst_rho = approx, r.worst_rho_triangle = t, r.worst_rho_vertex = v;
          continue;
        }
        const Rational q = radius_edge_squared(
            std::array{mesh.sites[tri[0]], mesh.sites[tri[1]], mesh.sites[tri[2]]}, mesh.metrics[v]);
        const double approx = std::sqrt(q.convert_to<double>());
        if (approx > r.worst_rho) r.worst_rho = approx, r.worst_rho_triangle = t, r.worst_rho_vertex = v;
        if (q > rho2) {
          r.rho_violations.add(v, t, -1, [&] {
            return name("triangle", t) + " has radius-edge ratio " + std::to_string(approx) + " > ρ₀ in the metric of " +
                   name("vertex", v);
          });
          break;
        }
      }
    if (o.gamma0)
      for (int i = 0; i < 3; ++i) {
        const int a = tri[i], b = tri[(i + 1) % 3];
        const double g = std::sqrt(geometry::tau_squared_estimate(nearest_doubles(mesh.metrics[a]), nearest_doubles(mesh.metrics[b])));
        if (g > r.worst_gamma) r.worst_gamma = g, r.worst_gamma_triangle = t;
        if (!predicates::tau_at_most(mesh.metrics[a], mesh.metrics[b], gamma2)) {
          r.gamma_violations.add(a, t, b, [&] {
            return name("triangle", t) + ": distortion between vertices " + std::to_string(a) + " and " + std::to_string(b) +
                   " is " + std::to_string(g) + " > γ₀";
          });
          break;
        }
      }
  }
}

}  // namespace

CertifyReport certify_mesh(const Mesh<Rational>& mesh, const CertifyOptions& o) {
  CertifyReport r;
  const std::size_t described = o.described_witnesses;
  r.uniform_violations = r.uniform_ties = r.rho_violations = r.gamma_violations = WitnessList(described);
  const EnclosedMesh m(mesh);
  const SiteTree tree(m.approx);
  const CellList cells = triangle_cells(mesh.triangles);
  const std::vector<std::pair<int, int>> edges = unique_edges(cells, mesh.sites.size());
  if (o.valid) {
    r.valid = check_triangulation(m, cells, described);
    check_segments(m, tree, edges, described, r);
  }
  const bool metrics = mesh.metrics.size() == mesh.sites.size();
  if (o.uniform && metrics) {
    r.uniform_checked = true;
    check_uniform(m, tree, o.threads, r);
  }
  if ((o.rho0 || o.gamma0) && metrics) check_quality_bounds(m, o, r);
  if (o.metric && metrics) {
    r.lengths = check_lengths(m, edges, o.length_range, described);
    r.quality = check_quality(m, o.min_quality, described);
    r.angles = check_angles(m, o.min_angle, described);
  }
  return r;
}

}  // namespace anisocert::oracle
