// The mean-ratio quality of triangles and tetrahedra in their vertices' metrics (metric_checks.hpp):
// one loop, a level per dimension.
#include "oracle/certify/metric_checks.hpp"

#include "predicates/filtered_sign.hpp"
#include "predicates/orientation3.hpp"
#include "predicates/point.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

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

// S = Σ ℓ_M² over the six edges of tetrahedron abcd: inputs a, b, c, d, then M (m11 m12 m13 m22
// m23 m33). Degree 2 in the coordinates, 1 in the metric; `groups` for its static bound
// (predicates::static_enclosure).
struct FormSum3Kernel {
  static constexpr std::size_t arity = 18;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    T S(0);
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        S = S + predicates::quadratic_form(x[12], x[13], x[14], x[15], x[16], x[17], T(x[3 * j] - x[3 * i]), T(x[3 * j + 1] - x[3 * i + 1]),
                                           T(x[3 * j + 2] - x[3 * i + 2]));
    return S;
  }
};

// det M of a 3 × 3 metric (m11 m12 m13 m22 m23 m33).
struct MetricDeterminant3Kernel {
  static constexpr std::size_t arity = 6;
  static constexpr std::array<int, arity> groups{1, 1, 1, 1, 1, 1};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return x[0] * (x[3] * x[5] - x[4] * x[4]) - x[1] * (x[1] * x[5] - x[4] * x[2]) + x[2] * (x[1] * x[4] - x[3] * x[2]);
  }
};

// 432 det(M) D² − q₀³ S³, D = det[b − a; c − a; d − a] (six volumes, orientation3.hpp's
// polynomial), S = Σ ℓ_M² over the six edges: positive or zero exactly when the tetrahedron's mean
// ratio 12 (3 V_M)^(2/3) / S, V_M = √det M · |D|/6, is at least q₀ (the regular tetrahedron: D² =
// 1/2 for unit edges, S = 6, 1).
struct Quality3Kernel {
  static constexpr std::size_t arity = 19;
  // (432 det(M) D², S): the two parts, shared by the decision and the enclosure of q.
  template <class T>
  static std::pair<T, T> parts(const std::array<T, arity>& x) {
    std::array<T, 12> p;
    std::array<T, 18> pm;
    std::array<T, 6> M;
    for (std::size_t i = 0; i < 18; ++i) pm[i] = x[i];
    for (std::size_t i = 0; i < 12; ++i) p[i] = x[i];
    for (std::size_t i = 0; i < 6; ++i) M[i] = x[12 + i];
    const T D = predicates::Orientation3Kernel::eval(p);
    return {T(432) * MetricDeterminant3Kernel::eval(M) * D * D, FormSum3Kernel::eval(pm)};
  }
  template <class T>
  static T eval(const std::array<T, arity>& x) {
    const auto [top, S] = parts(x);
    return top - x[18] * S * S * S;
  }
};

// The cube root of an enclosure, widened by two ulps each way (glibc's cbrt is within one).
FilterInterval cbrt(const FilterInterval& x) {
  const auto down = [](double v) { return std::nextafter(std::nextafter(v, -INFINITY), -INFINITY); };
  const auto up = [](double v) { return std::nextafter(std::nextafter(v, INFINITY), INFINITY); };
  return {std::max(0.0, down(std::cbrt(std::max(0.0, x.lo)))), up(std::cbrt(x.hi))};
}

// Per dimension, what the one loop below asks of an element: whether it can be measured, its
// vertices, the enclosure of its quality in one vertex's metric, and the exact decision of
// quality ≥ q₀ (the sign of the kernel; q0k = q₀² in 2D, q₀³ in 3D).
// Whether vertices u and v of a triangle mesh have the same metric, exactly (the enclosures
// first; a tetrahedral mesh keeps classes of equal metrics, EnclosedMesh3::same_metric).
bool same_metric_of(const EnclosedMesh& m, int u, int v) {
  const auto &a = m.metric[static_cast<std::size_t>(u)], &b = m.metric[static_cast<std::size_t>(v)];
  if (a.m11.lo != b.m11.lo || a.m11.hi != b.m11.hi || a.m22.lo != b.m22.lo || a.m22.hi != b.m22.hi) return false;
  return m.mesh.metrics[static_cast<std::size_t>(u)] == m.mesh.metrics[static_cast<std::size_t>(v)];
}

struct Triangles {
  const EnclosedMesh& m;
  static constexpr const char* kind = "triangle";
  static constexpr int power = 2;
  std::size_t size() const { return m.mesh.triangles.size(); }
  const std::array<int, 3>& vertices(std::size_t t) const { return m.mesh.triangles[t]; }
  bool same_metric(int u, int v) const { return same_metric_of(m, u, v); }
  bool measurable(std::size_t t) const {  // flat or clockwise: validity reports it
    const auto& tri = vertices(t);
    return m.orientation(tri[0], tri[1], tri[2]) == Sign::positive;
  }
  FilterInterval quality(std::size_t t, int v) const {
    const auto& tri = vertices(t);
    const auto &a = m.site[tri[0]], &b = m.site[tri[1]], &c = m.site[tri[2]];
    const auto& M = m.metric[v];
    const auto p = quality_parts(edges_of(a.x, a.y, b.x, b.y, c.x, c.y), M.m11, M.m12, M.m22);
    return sqrt(FilterInterval(12) * p.det) * p.D / p.S;
  }
  Sign decide(std::size_t t, int v, const FilterInterval& q0k, const Rational& q0k_exact) const {
    const auto& tri = vertices(t);
    const auto &a = m.site[tri[0]], &b = m.site[tri[1]], &c = m.site[tri[2]];
    const auto& M = m.metric[v];
    return predicates::interval_then_exact<QualityKernel>(
        std::array<FilterInterval, 10>{a.x, a.y, b.x, b.y, c.x, c.y, M.m11, M.m12, M.m22, q0k}, [&] {
          const auto& s = m.mesh.sites;
          const auto& n = m.mesh.metrics;
          return std::array<Rational, 10>{s[tri[0]].x, s[tri[0]].y, s[tri[1]].x, s[tri[1]].y, s[tri[2]].x,
                                          s[tri[2]].y, n[v].m11, n[v].m12, n[v].m22, q0k_exact};
        });
  }
};

struct Tetrahedra {
  const EnclosedMesh3& m;
  static constexpr const char* kind = "tetrahedron";
  static constexpr int power = 3;
  std::size_t size() const { return m.mesh.tetrahedra.size(); }
  const std::array<int, 4>& vertices(std::size_t t) const { return m.mesh.tetrahedra[t]; }
  bool same_metric(int u, int v) const { return m.same_metric(u, v); }
  bool measurable(std::size_t t) const {  // flat: validity reports it; either orientation is measured (D² alone)
    return m.orientation(t) != Sign::zero;
  }
  template <class T, class P, class Mt>
  static std::array<T, 19> arguments(const std::array<int, 4>& k, const std::vector<P>& x, const Mt& M, const T& q0k) {
    std::array<T, 19> a;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& p = x[static_cast<std::size_t>(k[i])];
      a[3 * i] = p.x, a[3 * i + 1] = p.y, a[3 * i + 2] = p.z;
    }
    a[12] = M.m11, a[13] = M.m12, a[14] = M.m13, a[15] = M.m22, a[16] = M.m23, a[17] = M.m33, a[18] = q0k;
    return a;
  }
  // q = (432 det M D² / S³)^(1/3), from the kernel's parts: each part enclosed by its static
  // bound when every input is a double (a binary file's), else the parts in intervals.
  FilterInterval quality(std::size_t t, int v) const {
    const auto& k = vertices(t);
    const auto vi = static_cast<std::size_t>(v);
    if (m.doubles(k, v)) {
      const auto x = arguments(k, m.approx, m.metric[vi], FilterInterval(0));
      std::array<double, 18> pm;
      for (std::size_t i = 0; i < 18; ++i) pm[i] = x[i].lo;  // points: lo = hi
      std::array<double, 12> p;
      std::array<double, 6> M;
      for (std::size_t i = 0; i < 12; ++i) p[i] = pm[i];
      for (std::size_t i = 0; i < 6; ++i) M[i] = pm[12 + i];
      const auto D = predicates::static_enclosure<predicates::Orientation3Kernel>(p);
      const auto S = predicates::static_enclosure<FormSum3Kernel>(pm);
      const auto det = predicates::static_enclosure<MetricDeterminant3Kernel>(M);
      if (D && S && det) return cbrt(FilterInterval(432) * *det * sqr(*D) / (*S * *S * *S));
    }
    const auto [top, S] = Quality3Kernel::parts(arguments(k, m.vertex, m.metric[vi], FilterInterval(0)));
    return cbrt(top / (S * S * S));
  }
  Sign decide(std::size_t t, int v, const FilterInterval& q0k, const Rational& q0k_exact) const {
    const auto& k = vertices(t);
    return predicates::interval_then_exact<Quality3Kernel>(arguments(k, m.vertex, m.metric[static_cast<std::size_t>(v)], q0k), [&] {
      return arguments(k, m.mesh.vertices, m.mesh.metrics[static_cast<std::size_t>(v)], q0k_exact);
    });
  }
};

// The mean ratio of every element in each of its vertices' metrics, the least over its vertices
// enclosed, the quantiles, and (with q₀) one witness per element below it, decided exactly.
template <class Level>
QualityReport check_quality_of(const Level& level, const std::optional<Rational>& min_quality, std::size_t described) {
  QualityReport r;
  r.violations = WitnessList(described);
  std::optional<Rational> q0k;
  FilterInterval q0ki;
  if (min_quality) q0k = Level::power == 2 ? *min_quality * *min_quality : *min_quality * *min_quality * *min_quality, q0ki = enclose(*q0k);
  std::vector<double> lows, highs;
  for (std::size_t t = 0; t < level.size(); ++t) {
    if (!level.measurable(t)) {
      ++r.undecided;
      continue;
    }
    FilterInterval q{INFINITY, INFINITY};
    bool reported = false;
    const auto& vs = level.vertices(t);
    for (std::size_t i = 0; i < vs.size(); ++i) {
      const int v = vs[i];
      // A metric equal to an earlier vertex's (a constant field) gives the same quality again.
      if (std::any_of(vs.begin(), vs.begin() + static_cast<std::ptrdiff_t>(i), [&](int u) { return level.same_metric(u, v); })) continue;
      FilterInterval qv = level.quality(t, v);
      qv.lo = std::max(qv.lo, 0.0);  // the exact value is positive (a measurable element, M positive definite)
      q = min(q, qv);
      if (q0k && !reported && level.decide(t, v, q0ki, *q0k) == Sign::negative) {
        reported = true;
        r.violations.add(v, static_cast<int>(t), -1, [&] {
          return std::string(Level::kind) + " " + std::to_string(t) + " has mean-ratio quality about " +
                 std::to_string((qv.lo + qv.hi) / 2) + " in the metric of vertex " + std::to_string(v) + ", below the bound";
        });
      }
    }
    ++r.measured;
    lows.push_back(q.lo), highs.push_back(q.hi);
    r.qualities.push_back((q.lo + q.hi) / 2);
    if (r.worst_triangle < 0 || q.lo < r.worst.lo) r.worst = q, r.worst_triangle = static_cast<int>(t);
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

}  // namespace

QualityReport check_quality(const EnclosedMesh& m, const std::optional<Rational>& min_quality, std::size_t described) {
  return check_quality_of(Triangles{m}, min_quality, described);
}

QualityReport check_quality(const EnclosedMesh3& m, const std::optional<Rational>& min_quality, std::size_t described) {
  return check_quality_of(Tetrahedra{m}, min_quality, described);
}

}  // namespace anisocert::oracle
