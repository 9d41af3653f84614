#include "oracle/certify/mesh_certifier.hpp"

#include "geometry/circumellipse.hpp"
#include "oracle/certify/site_tree.hpp"
#include "geometry/distortion_estimate.hpp"
#include "geometry/ellipse_box.hpp"
#include "numbers/filter_interval.hpp"
#include "predicates/distortion.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace anisocert::oracle {

using predicates::Point2;
using predicates::Sym2;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();


// The locally uniform check on one scalar type (double when every input is a double exactly).
// An interval around a coordinate or metric entry: the double itself, or a rational enclosed.
FilterInterval enclose(double s) { return FilterInterval(s); }
FilterInterval enclose(const Rational& s) { return FilterInterval::around(s); }
Point2<FilterInterval> enclose(const Point2<double>& p) { return {enclose(p.x), enclose(p.y)}; }
Point2<FilterInterval> enclose(const Point2<Rational>& p) { return {enclose(p.x), enclose(p.y)}; }
template <class S>
Sym2<FilterInterval> enclose(const Sym2<S>& m) {
  return {enclose(m.m11), enclose(m.m12), enclose(m.m22)};
}

template <class S>
void check_uniform(const std::vector<Point2<S>>& p, const std::vector<Sym2<S>>& M, const Mesh<Rational>& mesh,
                   const SiteTree& tree, CertifyReport& r) {
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    if (predicates::orientation(p[tri[0]], p[tri[1]], p[tri[2]]) != Sign::positive) continue;  // `valid` reports it
    for (int v : tri) {
      const Sym2<S>& m = M[v];
      // The M_v-circumellipse of the triangle, enclosed (geometry/circumellipse.hpp), and the box of
      // the M_v-ball around it: the sites outside that box are outside the ellipse, the rest are
      // decided by the exact in-circle predicate.
      const Sym2<FilterInterval> mi = enclose(m);
      const geometry::Circumellipse<FilterInterval> c =
          geometry::circumellipse(enclose(p[tri[0]]), enclose(p[tri[1]]), enclose(p[tri[2]]), mi);
      const geometry::HalfWidths<FilterInterval> h = geometry::ellipse_half_widths(mi, c.r2);
      const double hx = h.hx.hi, hy = h.hy.hi;
      const FilterInterval &cx = c.cx, &cy = c.cy;
      const bool bounded = std::isfinite(cx.lo) && std::isfinite(cx.hi) && std::isfinite(cy.lo) && std::isfinite(cy.hi) &&
                           std::isfinite(hx) && std::isfinite(hy);
      const double qx0 = bounded ? cx.lo - hx : -inf, qx1 = bounded ? cx.hi + hx : inf;
      const double qy0 = bounded ? cy.lo - hy : -inf, qy1 = bounded ? cy.hi + hy : inf;
      tree.visit(qx0, qx1, qy0, qy1, [&](int s) {
        if (s == tri[0] || s == tri[1] || s == tri[2]) return;
        ++r.incircle_tests;
        const Sign in = predicates::incircle(p[tri[0]], p[tri[1]], p[tri[2]], p[s], m);
        if (in == Sign::negative) return;
        MeshWitness w{v, t, s,
                      "site " + std::to_string(s) + (in == Sign::positive ? " is strictly inside" : " is exactly on") +
                          " the circumellipse of triangle " + std::to_string(t) + " in the metric of vertex " +
                          std::to_string(v)};
        (in == Sign::positive ? r.uniform_violations : r.uniform_ties).push_back(std::move(w));
      });
    }
  }
}

bool exactly_double(const Rational& q) {
  const double d = q.convert_to<double>();
  return std::isfinite(d) && Rational(d) == q;
}

// sign(x) for x = the segment parameter of p on [a, b] (exact), or nothing when p is off the line.
std::optional<Rational> parameter_on(const Point2<Rational>& a, const Point2<Rational>& b, const Point2<Rational>& p) {
  if (predicates::orientation(a, b, p) != Sign::zero) return std::nullopt;
  const Rational len = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  return ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / len;
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

}  // namespace

CertifyReport certify_mesh(const Mesh<Rational>& mesh, const CertifyOptions& o) {
  CertifyReport r;
  std::vector<Point2<double>> approx;
  for (const auto& p : mesh.sites) approx.push_back({p.x.convert_to<double>(), p.y.convert_to<double>()});
  const SiteTree tree(approx);
  if (o.valid) {
    std::vector<Cell> cells;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      cells.push_back({"triangle " + std::to_string(t), {mesh.triangles[t].begin(), mesh.triangles[t].end()}});
    r.valid = check_triangulation(mesh.sites, mesh.domain, cells);
    std::set<std::pair<int, int>> edges;
    for (const auto& t : mesh.triangles)
      for (int i = 0; i < 3; ++i) edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
    for (std::size_t k = 0; k < mesh.segments.size(); ++k) {
      const int a = mesh.segments[k].first, b = mesh.segments[k].second;
      std::vector<std::pair<Rational, int>> on;
      const double xa = approx[a].x, xb = approx[b].x, ya = approx[a].y, yb = approx[b].y;
      tree.visit(std::min(xa, xb), std::max(xa, xb), std::min(ya, yb), std::max(ya, yb), [&](int s) {
        if (const auto t = parameter_on(mesh.sites[a], mesh.sites[b], mesh.sites[s]); t && *t >= 0 && *t <= 1)
          on.emplace_back(*t, s);
      });
      std::sort(on.begin(), on.end());
      for (std::size_t i = 0; i + 1 < on.size(); ++i)
        if (!edges.count(std::minmax(on[i].second, on[i + 1].second)))
          r.segment_failures.push_back("segment " + std::to_string(k) + " is not a union of edges: sites " +
                                       std::to_string(on[i].second) + " and " + std::to_string(on[i + 1].second) +
                                       " are consecutive on it but not joined by an edge");
    }
  }
  if (o.uniform) {
    r.uniform_checked = true;
    bool doubles = true;
    for (const auto& p : mesh.sites) doubles = doubles && exactly_double(p.x) && exactly_double(p.y);
    for (const auto& m : mesh.metrics) doubles = doubles && exactly_double(m.m11) && exactly_double(m.m12) && exactly_double(m.m22);
    if (doubles) {
      std::vector<Sym2<double>> M;
      for (const auto& m : mesh.metrics) M.push_back({m.m11.convert_to<double>(), m.m12.convert_to<double>(), m.m22.convert_to<double>()});
      check_uniform<double>(approx, M, mesh, tree, r);
    } else {
      check_uniform<Rational>(mesh.sites, mesh.metrics, mesh, tree, r);
    }
  }
  if (o.rho0 || o.gamma0) {
    const Rational rho2 = o.rho0 ? *o.rho0 * *o.rho0 : Rational(0), gamma2 = o.gamma0 ? *o.gamma0 * *o.gamma0 : Rational(0);
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
      const auto& tri = mesh.triangles[t];
      const std::array<Point2<Rational>, 3> pts{mesh.sites[tri[0]], mesh.sites[tri[1]], mesh.sites[tri[2]]};
      if (predicates::orientation(pts[0], pts[1], pts[2]) == Sign::zero) continue;  // flat: `valid` reports it
      if (o.rho0)
        for (int v : tri) {
          const FilterInterval e =
              radius_edge_squared(std::array{enclose(pts[0]), enclose(pts[1]), enclose(pts[2])}, enclose(mesh.metrics[v]));
          const double hi = FilterInterval::around(rho2).lo;
          if (e.hi < hi) {  // decided by the enclosure: ≤ ρ₀²
            const double approx = std::sqrt((e.lo + e.hi) / 2);
            if (approx > r.worst_rho) r.worst_rho = approx, r.worst_rho_triangle = t, r.worst_rho_vertex = v;
            continue;
          }
          const Rational q = radius_edge_squared(pts, mesh.metrics[v]);
          const double approx = std::sqrt(q.convert_to<double>());
          if (approx > r.worst_rho) r.worst_rho = approx, r.worst_rho_triangle = t, r.worst_rho_vertex = v;
          if (q > rho2)
            r.rho_violations.push_back({v, t, -1, "triangle " + std::to_string(t) + " has radius-edge ratio " +
                                                      std::to_string(approx) + " > ρ₀ in the metric of vertex " +
                                                      std::to_string(v)});
        }
      if (o.gamma0)
        for (int i = 0; i < 3; ++i) {
          const int a = tri[i], b = tri[(i + 1) % 3];
          const double g = std::sqrt(geometry::tau_squared_estimate(nearest_doubles(mesh.metrics[a]), nearest_doubles(mesh.metrics[b])));
          if (g > r.worst_gamma) r.worst_gamma = g, r.worst_gamma_triangle = t;
          if (!predicates::tau_at_most(mesh.metrics[a], mesh.metrics[b], gamma2))
            r.gamma_violations.push_back({a, t, b, "triangle " + std::to_string(t) + ": distortion between vertices " +
                                                       std::to_string(a) + " and " + std::to_string(b) + " is " +
                                                       std::to_string(g) + " > γ₀"});
        }
    }
  }
  return r;
}

}  // namespace anisocert::oracle
