#include "oracle/certify/mesh_certifier.hpp"

#include "predicates/distortion.hpp"
#include "numbers/filter_interval.hpp"
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

// Outward interval quotient and square root (IEEE operations are correctly rounded; one ulp
// outward covers the exact result). An interval divisor containing 0 gives everything.
FilterInterval divide(const FilterInterval& a, const FilterInterval& b) {
  if (!(b.lo > 0 || b.hi < 0)) return {-inf, inf};
  const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return FilterInterval::widen(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
}
double sqrt_up(double x) { return x <= 0 ? 0 : std::nextafter(std::sqrt(x), inf); }

// Sites in a static k-d tree (median splits, leaves of at most 8), for the circumellipse queries:
// adapts to clustered sites, where a uniform grid would scan crowded cells. The coordinates are
// the sites' nearest doubles, within half an ulp of the exact ones, so every query box is widened
// by two ulps on each side before it is compared with them.
class SiteTree {
 public:
  explicit SiteTree(const std::vector<Point2<double>>& p) : p_(p), order_(p.size()) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    build(0, order_.size(), 0);
  }
  template <class F>
  void visit(double x0, double x1, double y0, double y1, F&& f) const {
    auto widen_down = [](double v) { return std::nextafter(std::nextafter(v, -inf), -inf); };
    auto widen_up = [](double v) { return std::nextafter(std::nextafter(v, inf), inf); };
    query(0, order_.size(), 0, widen_down(x0), widen_up(x1), widen_down(y0), widen_up(y1), f);
  }

 private:
  double coord(int i, int axis) const { return axis == 0 ? p_[i].x : p_[i].y; }
  void build(std::size_t lo, std::size_t hi, int axis) {
    if (hi - lo <= 8) return;
    const std::size_t mid = (lo + hi) / 2;
    std::nth_element(order_.begin() + lo, order_.begin() + mid, order_.begin() + hi,
                     [&](int a, int b) { return coord(a, axis) < coord(b, axis); });
    build(lo, mid, 1 - axis);
    build(mid + 1, hi, 1 - axis);
  }
  template <class F>
  void query(std::size_t lo, std::size_t hi, int axis, double x0, double x1, double y0, double y1, F& f) const {
    if (hi - lo <= 8) {
      for (std::size_t k = lo; k < hi; ++k) {
        const auto& q = p_[order_[k]];
        if (q.x >= x0 && q.x <= x1 && q.y >= y0 && q.y <= y1) f(order_[k]);
      }
      return;
    }
    const std::size_t mid = (lo + hi) / 2;
    const int m = order_[mid];
    const double split = coord(m, axis), low = axis == 0 ? x0 : y0, high = axis == 0 ? x1 : y1;
    if (p_[m].x >= x0 && p_[m].x <= x1 && p_[m].y >= y0 && p_[m].y <= y1) f(m);
    if (low <= split) query(lo, mid, 1 - axis, x0, x1, y0, y1, f);
    if (high >= split) query(mid + 1, hi, 1 - axis, x0, x1, y0, y1, f);
  }
  const std::vector<Point2<double>>& p_;
  std::vector<int> order_;
};

// The locally uniform check on one scalar type (double when every input is a double exactly).
template <class S>
void check_uniform(const std::vector<Point2<S>>& p, const std::vector<Sym2<S>>& M, const Mesh<Rational>& mesh,
                   const SiteTree& tree, CertifyReport& r) {
  auto iv = [](const S& s) {
    if constexpr (std::is_same_v<S, double>) return FilterInterval(s);
    else return FilterInterval::around(s);
  };
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    if (predicates::orientation(p[tri[0]], p[tri[1]], p[tri[2]]) != Sign::positive) continue;  // `valid` reports it
    for (int v : tri) {
      const Sym2<S>& m = M[v];
      // The M-circumellipse of the triangle, enclosed: centre a + x with [g1; g2] x = [Q(d1); Q(d2)]/2.
      const FilterInterval ax = iv(p[tri[0]].x), ay = iv(p[tri[0]].y), m11 = iv(m.m11), m12 = iv(m.m12), m22 = iv(m.m22);
      const FilterInterval d1x = iv(p[tri[1]].x) - ax, d1y = iv(p[tri[1]].y) - ay;
      const FilterInterval d2x = iv(p[tri[2]].x) - ax, d2y = iv(p[tri[2]].y) - ay;
      const FilterInterval g1x = m11 * d1x + m12 * d1y, g1y = m12 * d1x + m22 * d1y;
      const FilterInterval g2x = m11 * d2x + m12 * d2y, g2y = m12 * d2x + m22 * d2y;
      const FilterInterval half(0.5);
      const FilterInterval q1 = half * (d1x * g1x + d1y * g1y), q2 = half * (d2x * g2x + d2y * g2y);
      const FilterInterval det = g1x * g2y - g1y * g2x;
      const FilterInterval x = divide(q1 * g2y - q2 * g1y, det), y = divide(g1x * q2 - g2x * q1, det);
      const FilterInterval r2 = x * (m11 * x + m12 * y) + y * (m12 * x + m22 * y);
      const FilterInterval detm = m11 * m22 - m12 * m12;
      const FilterInterval hx2 = divide(r2 * m22, detm), hy2 = divide(r2 * m11, detm);
      const double hx = sqrt_up(hx2.hi), hy = sqrt_up(hy2.hi);
      const FilterInterval cx = ax + x, cy = ay + y;
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

// An enclosure of the radius-edge ratio² of a triangle in metric M (outward interval arithmetic),
// to decide "≤ ρ₀²" without rationals when it is clear.
FilterInterval radius_edge_squared_enclosure(const std::array<Point2<Rational>, 3>& t, const Sym2<Rational>& M) {
  auto iv = [](const Rational& q) { return FilterInterval::around(q); };
  const FilterInterval m11 = iv(M.m11), m12 = iv(M.m12), m22 = iv(M.m22);
  auto q = [&](const FilterInterval& dx, const FilterInterval& dy) { return dx * (m11 * dx + m12 * dy) + dy * (m12 * dx + m22 * dy); };
  const FilterInterval ax = iv(t[0].x), ay = iv(t[0].y);
  const FilterInterval d1x = iv(t[1].x) - ax, d1y = iv(t[1].y) - ay, d2x = iv(t[2].x) - ax, d2y = iv(t[2].y) - ay;
  const FilterInterval g1x = m11 * d1x + m12 * d1y, g1y = m12 * d1x + m22 * d1y;
  const FilterInterval g2x = m11 * d2x + m12 * d2y, g2y = m12 * d2x + m22 * d2y;
  const FilterInterval half(0.5), q1 = half * q(d1x, d1y), q2 = half * q(d2x, d2y), det = g1x * g2y - g1y * g2x;
  const FilterInterval x = divide(q1 * g2y - q2 * g1y, det), y = divide(g1x * q2 - g2x * q1, det);
  const FilterInterval e3 = q(iv(t[2].x) - iv(t[1].x), iv(t[2].y) - iv(t[1].y));
  const FilterInterval e1 = q(d1x, d1y), e2 = q(d2x, d2y);
  const FilterInterval shortest{std::min({e1.lo, e2.lo, e3.lo}), std::min({e1.hi, e2.hi, e3.hi})};
  return divide(q(x, y), shortest);
}

// Radius-edge ratio² of a triangle in metric M (exact): Q_M(centre − a) / min edge Q_M.
Rational radius_edge_squared(const std::array<Point2<Rational>, 3>& t, const Sym2<Rational>& M) {
  auto q = [&](const Rational& dx, const Rational& dy) { return predicates::quadratic_form(M.m11, M.m12, M.m22, dx, dy); };
  const Rational d1x = t[1].x - t[0].x, d1y = t[1].y - t[0].y, d2x = t[2].x - t[0].x, d2y = t[2].y - t[0].y;
  const Rational g1x = M.m11 * d1x + M.m12 * d1y, g1y = M.m12 * d1x + M.m22 * d1y;
  const Rational g2x = M.m11 * d2x + M.m12 * d2y, g2y = M.m12 * d2x + M.m22 * d2y;
  const Rational q1 = q(d1x, d1y) / 2, q2 = q(d2x, d2y) / 2, det = g1x * g2y - g1y * g2x;
  const Rational x = (q1 * g2y - q2 * g1y) / det, y = (g1x * q2 - g2x * q1) / det;
  const Rational shortest = std::min({q(d1x, d1y), q(d2x, d2y), q(t[2].x - t[1].x, t[2].y - t[1].y)});
  return q(x, y) / shortest;
}

double tau_squared_approx(const Sym2<Rational>& A, const Sym2<Rational>& B) {
  // Largest generalized eigenvalue of (B, A) and of (A, B): roots of det(B − λA) = 0.
  auto largest = [](const Sym2<Rational>& P, const Sym2<Rational>& Q) {
    const double a = P.m11.convert_to<double>(), b = P.m12.convert_to<double>(), c = P.m22.convert_to<double>();
    const double d = Q.m11.convert_to<double>(), e = Q.m12.convert_to<double>(), f = Q.m22.convert_to<double>();
    const double A2 = a * c - b * b, B1 = -(a * f + c * d - 2 * b * e), C0 = d * f - e * e;
    return (-B1 + std::sqrt(std::max(0.0, B1 * B1 - 4 * A2 * C0))) / (2 * A2);
  };
  return std::max(largest(A, B), largest(B, A));
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
      const auto [a, b] = mesh.segments[k];
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
          const FilterInterval e = radius_edge_squared_enclosure(pts, mesh.metrics[v]);
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
          const double g = std::sqrt(tau_squared_approx(mesh.metrics[a], mesh.metrics[b]));
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
