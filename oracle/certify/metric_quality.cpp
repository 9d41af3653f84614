// The mean-ratio quality of triangles in their vertices' metrics (metric_checks.hpp).
#include "oracle/certify/metric_checks.hpp"

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::oracle {
namespace {

// D = twice the signed area of abc, S = Σ ℓ_M², det M: the parts of the mean ratio 2√3 √det M · D / S.
// The edge vectors u = b − a, w = c − a, v = c − b and D do not depend on M.
template <class T>
struct Edges {
  T ux, uy, wx, wy, vx, vy, D;
};
template <class T>
Edges<T> edges_of(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy) {
  const T ux = bx - ax, uy = by - ay, wx = cx - ax, wy = cy - ay;
  return {ux, uy, wx, wy, T(cx - bx), T(cy - by), T(ux * wy - uy * wx)};
}
template <class T>
struct QualityParts {
  T D, S, det;
};
template <class T>
QualityParts<T> quality_parts(const Edges<T>& e, const T& m11, const T& m12, const T& m22) {
  return {e.D,
          T(predicates::quadratic_form(m11, m12, m22, e.ux, e.uy) + predicates::quadratic_form(m11, m12, m22, e.wx, e.wy) +
            predicates::quadratic_form(m11, m12, m22, e.vx, e.vy)),
          T(m11 * m22 - m12 * m12)};
}

// 12 det(M) D² − q₀² S²: positive or zero exactly when the mean ratio is at least q₀ (for D > 0).
struct QualityKernel {
  static constexpr std::size_t arity = 10;
  template <class T>
  static T eval(const std::array<T, arity>& x) {
    const QualityParts<T> p = quality_parts<T>(edges_of<T>(x[0], x[1], x[2], x[3], x[4], x[5]), x[6], x[7], x[8]);
    return T(12) * p.det * p.D * p.D - x[9] * p.S * p.S;
  }
};

}  // namespace

QualityReport check_quality(const EnclosedMesh& m, const std::optional<Rational>& min_quality, std::size_t described) {
  QualityReport r;
  r.violations = WitnessList(described);
  const auto& tris = m.mesh.triangles;
  std::optional<Rational> q2;
  FilterInterval q2i;
  if (min_quality) q2 = *min_quality * *min_quality, q2i = enclose(*q2);
  std::vector<double> lows, highs;
  for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
    const auto& tri = tris[t];
    if (m.orientation(tri[0], tri[1], tri[2]) != Sign::positive) {  // flat or clockwise: validity reports it
      ++r.undecided;
      continue;
    }
    const auto &a = m.site[tri[0]], &b = m.site[tri[1]], &c = m.site[tri[2]];
    const Edges<FilterInterval> e = edges_of(a.x, a.y, b.x, b.y, c.x, c.y);
    FilterInterval q{INFINITY, INFINITY};
    bool reported = false;
    for (const int v : tri) {
      const auto& M = m.metric[v];
      const auto p = quality_parts(e, M.m11, M.m12, M.m22);
      FilterInterval qv = sqrt(FilterInterval(12) * p.det) * p.D / p.S;
      qv.lo = std::max(qv.lo, 0.0);  // the exact value is positive (D > 0, M positive definite)
      q = min(q, qv);
      if (q2 && !reported) {
        const Sign s = predicates::interval_then_exact<QualityKernel>(
            std::array<FilterInterval, 10>{a.x, a.y, b.x, b.y, c.x, c.y, M.m11, M.m12, M.m22, q2i}, [&] {
              const auto& s = m.mesh.sites;
              const auto& n = m.mesh.metrics;
              return std::array<Rational, 10>{s[tri[0]].x, s[tri[0]].y, s[tri[1]].x, s[tri[1]].y, s[tri[2]].x,
                                              s[tri[2]].y, n[v].m11, n[v].m12, n[v].m22, *q2};
            });
        if (s == Sign::negative) {
          reported = true;
          r.violations.add(v, t, -1, [&] {
            return "triangle " + std::to_string(t) + " has mean-ratio quality about " + std::to_string((qv.lo + qv.hi) / 2) +
                   " in the metric of vertex " + std::to_string(v) + ", below the bound";
          });
        }
      }
    }
    ++r.measured;
    lows.push_back(q.lo), highs.push_back(q.hi);
    r.qualities.push_back((q.lo + q.hi) / 2);
    if (r.worst_triangle < 0 || q.lo < r.worst.lo) r.worst = q, r.worst_triangle = t;
  }
  // The p-quantile of the exact values lies between the p-quantiles of the lower and upper ends
  // (order statistics are monotone in every value).
  if (!lows.empty())
    for (const double p : {0.01, 0.05, 0.25, 0.5}) {
      const auto k = static_cast<std::ptrdiff_t>(p * static_cast<double>(lows.size() - 1));
      std::nth_element(lows.begin(), lows.begin() + k, lows.end());
      std::nth_element(highs.begin(), highs.begin() + k, highs.end());
      r.quantiles.push_back({p, FilterInterval(lows[k], highs[k])});
    }
  return r;
}

}  // namespace anisocert::oracle
