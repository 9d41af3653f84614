#include "oracle/certify/mesh_certifier3.hpp"

#include "geometry/circumellipsoid.hpp"
#include "geometry/distortion_estimate.hpp"
#include "oracle/parallel_for.hpp"
#include "predicates/distortion.hpp"
#include "predicates/insphere.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::oracle {
namespace {

using I = FilterInterval;

// The vertices in a uniform grid over their approximations, about one per cell: the candidates of
// a box are the vertices of the cells it meets, then those whose approximation lies in it.
class VertexGrid {
 public:
  explicit VertexGrid(const std::vector<predicates::Point3<double>>& p) : p_(p) {
    lo_ = {INFINITY, INFINITY, INFINITY}, hi_ = {-INFINITY, -INFINITY, -INFINITY};
    for (const auto& q : p) {
      const std::array<double, 3> c{q.x, q.y, q.z};
      for (int k = 0; k < 3; ++k) lo_[k] = std::min(lo_[k], c[k]), hi_[k] = std::max(hi_[k], c[k]);
    }
    const double per_axis = std::max(1.0, std::cbrt(static_cast<double>(p.size())));
    for (int k = 0; k < 3; ++k) {
      n_[k] = std::max(1, static_cast<int>(per_axis));
      step_[k] = hi_[k] > lo_[k] ? (hi_[k] - lo_[k]) / n_[k] : 1;
    }
    std::vector<std::pair<std::size_t, int>> keyed;
    keyed.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) keyed.emplace_back(cell({p[i].x, p[i].y, p[i].z}), static_cast<int>(i));
    std::sort(keyed.begin(), keyed.end());
    start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
    for (const auto& [c, i] : keyed) ++start_[c + 1], ids_.push_back(i);
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  }

  // The vertices whose approximations lie in [lo, hi] (closed).
  void query(const std::array<double, 3>& lo, const std::array<double, 3>& hi, std::vector<int>& out) const {
    out.clear();
    std::array<int, 3> a{}, b{};
    for (int k = 0; k < 3; ++k) {
      if (hi[k] < lo_[k] || lo[k] > hi_[k]) return;
      a[k] = index(k, lo[k]), b[k] = index(k, hi[k]);
    }
    for (int x = a[0]; x <= b[0]; ++x)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int z = a[2]; z <= b[2]; ++z) {
          const std::size_t c = (static_cast<std::size_t>(x) * n_[1] + y) * n_[2] + z;
          for (std::size_t j = start_[c]; j < start_[c + 1]; ++j) {
            const auto& q = p_[static_cast<std::size_t>(ids_[j])];
            if (q.x >= lo[0] && q.x <= hi[0] && q.y >= lo[1] && q.y <= hi[1] && q.z >= lo[2] && q.z <= hi[2]) out.push_back(ids_[j]);
          }
        }
  }

 private:
  int index(int k, double v) const {
    const double t = std::floor((v - lo_[k]) / step_[k]);
    return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(n_[k] - 1)));  // clamped in doubles: no overflow
  }
  std::size_t cell(const std::array<double, 3>& v) const {
    return (static_cast<std::size_t>(index(0, v[0])) * n_[1] + index(1, v[1])) * n_[2] + index(2, v[2]);
  }
  const std::vector<predicates::Point3<double>>& p_;
  std::array<double, 3> lo_, hi_, step_;
  std::array<int, 3> n_;
  std::vector<std::size_t> start_;
  std::vector<int> ids_;
};

I det3(const std::array<std::array<I, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

std::array<I, 3> times(const predicates::Sym3<I>& M, const std::array<I, 3>& v) {
  return {M.m11 * v[0] + M.m12 * v[1] + M.m13 * v[2], M.m12 * v[0] + M.m22 * v[1] + M.m23 * v[2], M.m13 * v[0] + M.m23 * v[1] + M.m33 * v[2]};
}

// The M-circumellipsoid of a tetrahedron, enclosed: its centre and r², and a box (lo, hi) that
// certainly holds it (with the approximate vertices within an ulp of it too).
struct Ellipsoid {
  std::array<I, 3> centre;
  I r2;
  std::array<double, 3> lo, hi;
};

// Cramer's determinants of the M-circumcentre (geometry/circumellipsoid.hpp) as kernels, for
// their static enclosures when every input is a double: inputs a, b, c, d, then M; component
// k < 3 a numerator, 3 the denominator. Degrees 4/3 (numerator) and 3/3 in the coordinates' and
// the metric's groups, inside the static range; translatable (differences from a).
template <int k>
struct CircumcentreKernel {
  static constexpr std::size_t arity = 18;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
  static constexpr std::array<int, arity> origin{0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, -1, -1, -1, -1, -1, -1};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const auto point = [&](std::size_t i) { return predicates::Point3<T>{x[3 * i], x[3 * i + 1], x[3 * i + 2]}; };
    const auto c = geometry::circumcentre_determinants(point(0), point(1), point(2), point(3),
                                                       predicates::Sym3<T>{x[12], x[13], x[14], x[15], x[16], x[17]});
    if constexpr (k < 3)
      return c.numerator[k];
    else
      return c.denominator;
  }
};

// The M-circumellipsoid from the static enclosures of Cramer's determinants when every input is a
// double (a binary file's); nothing when an input is not one, or the denominator's enclosure holds 0.
std::optional<geometry::Circumellipsoid<I>> static_circumellipsoid(const EnclosedMesh3& m, const std::array<int, 4>& t, int v) {
  const auto vi = static_cast<std::size_t>(v);
  if (!m.doubles(t, v)) return std::nullopt;
  const auto& M = m.metric[vi];
  std::array<double, 18> x;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& p = m.approx[static_cast<std::size_t>(t[i])];
    x[3 * i] = p.x, x[3 * i + 1] = p.y, x[3 * i + 2] = p.z;
  }
  x[12] = M.m11.lo, x[13] = M.m12.lo, x[14] = M.m13.lo, x[15] = M.m22.lo, x[16] = M.m23.lo, x[17] = M.m33.lo;
  // The four kernels share their inputs' translation: one elimination gives the four values that
  // predicates::static_enclosure would compute one by one.
  const auto y = predicates::translated<CircumcentreKernel<3>>(x);
  const auto at = [&](std::size_t i) { return predicates::Point3<double>{y[3 * i], y[3 * i + 1], y[3 * i + 2]}; };
  const auto values = geometry::circumcentre_determinants(at(0), at(1), at(2), at(3), predicates::Sym3<double>{y[12], y[13], y[14], y[15], y[16], y[17]});
  const auto enclosed = [&]<int k>(CircumcentreKernel<k>) {
    return predicates::static_enclosure_of_value<CircumcentreKernel<k>, predicates::translated_error_model<CircumcentreKernel<k>>>(
        y, k < 3 ? values.numerator[static_cast<std::size_t>(k)] : values.denominator);
  };
  const auto n0 = enclosed(CircumcentreKernel<0>{}), n1 = enclosed(CircumcentreKernel<1>{}), n2 = enclosed(CircumcentreKernel<2>{}),
             d = enclosed(CircumcentreKernel<3>{});
  if (!n0 || !n1 || !n2 || !d || d->has_zero()) return std::nullopt;
  return geometry::circumellipsoid_of(geometry::CramerDeterminants<I>{{*n0, *n1, *n2}, *d}, M);
}

// The diagonal of M⁻¹ (cofactor over det M), enclosed; nothing when det M's enclosure is not
// positive. Once per vertex: it spans the box of every ellipsoid in M.
std::optional<std::array<I, 3>> inverse_diagonal(const predicates::Sym3<I>& M) {
  const I detM = det3({{{M.m11, M.m12, M.m13}, {M.m12, M.m22, M.m23}, {M.m13, M.m23, M.m33}}});
  if (!(detM.lo > 0)) return std::nullopt;
  return std::array<I, 3>{(M.m22 * M.m33 - M.m23 * M.m23) / detM, (M.m11 * M.m33 - M.m13 * M.m13) / detM, (M.m11 * M.m22 - M.m12 * M.m12) / detM};
}

// The enclosure, or nothing when intervals cannot give one (the static enclosures of Cramer's
// determinants when every input is a double, else intervals throughout). The centre is a + x with
// 2(q − a)ᵀ M x = (q − a)ᵀ M (q − a) for q = b, c, d; r² = xᵀMx; the ellipsoid
// {y : (y − c)ᵀ M (y − c) ≤ r²} spans c_i ± √(r² (M⁻¹)_ii) along axis i.
std::optional<Ellipsoid> enclose_ellipsoid(const EnclosedMesh3& m, const std::array<int, 4>& t, int v,
                                           const std::optional<std::array<I, 3>>& inverse_diagonal) {
  if (!inverse_diagonal) return std::nullopt;
  const predicates::Sym3<I>& M = m.metric[static_cast<std::size_t>(v)];
  const auto at = [&](std::size_t i) -> const predicates::Point3<I>& { return m.vertex[static_cast<std::size_t>(t[i])]; };
  const auto fast = static_circumellipsoid(m, t, v);
  auto c = fast ? *fast : geometry::circumellipsoid(at(0), at(1), at(2), at(3), M);  // an unsure determinant: the whole line
  if (!std::isfinite(c.r2.lo) || !std::isfinite(c.r2.hi) || c.r2.lo < 0) {
    // Intervals could not bound the centre (a nearly flat tetrahedron, a stretched metric: the
    // determinant's enclosure holds 0); the exact centre and radius, each enclosed, rather than
    // every vertex as a candidate (a graded mesh of a million tetrahedra at 100 : 1 was still being
    // certified after 20 minutes; 40 s since).
    const auto& q = m.mesh.vertices;
    const auto exact = geometry::circumellipsoid(q[static_cast<std::size_t>(t[0])], q[static_cast<std::size_t>(t[1])], q[static_cast<std::size_t>(t[2])],
                                                 q[static_cast<std::size_t>(t[3])], m.mesh.metrics[static_cast<std::size_t>(v)]);
    c = {{enclose(exact.x[0]), enclose(exact.x[1]), enclose(exact.x[2])}, enclose(exact.r2)};
  }
  const auto& x = c.x;
  const I& r2 = c.r2;
  if (!std::isfinite(r2.lo) || !std::isfinite(r2.hi) || r2.lo < 0) return std::nullopt;
  const auto& a = at(0);
  Ellipsoid e{{a.x + x[0], a.y + x[1], a.z + x[2]}, r2, {}, {}};
  for (std::size_t i = 0; i < 3; ++i) {
    const I half = sqrt(r2 * (*inverse_diagonal)[i]);
    double lo = (e.centre[i] - half).lo, hi = (e.centre[i] + half).hi;
    if (!std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
    // The grid holds approximations within an ulp of the exact vertices.
    e.lo[i] = I::next_down(I::next_down(lo)), e.hi[i] = I::next_up(I::next_up(hi));
  }
  return e;
}

// LU Definition 3.10's radius-edge ratio squared of tetrahedron t in metric M: r² over the
// shortest squared edge, T = FilterInterval (an enclosure) or Rational (exact).
template <class T>
T radius_edge_squared(const std::array<predicates::Point3<T>, 4>& p, const predicates::Sym3<T>& M) {
  using std::min;
  T shortest = predicates::quadratic_form(M, T(p[1].x - p[0].x), T(p[1].y - p[0].y), T(p[1].z - p[0].z));
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      shortest = min(shortest, predicates::quadratic_form(M, T(p[j].x - p[i].x), T(p[j].y - p[i].y), T(p[j].z - p[i].z)));
  return geometry::circumellipsoid(p[0], p[1], p[2], p[3], M).r2 / shortest;
}

// ρ ≤ ρ₀ in every vertex's metric and γ ≤ γ₀ between the vertices of every tetrahedron (the 2D
// check's twin in mesh_certifier.cpp, one witness per tetrahedron for each). A flat tetrahedron
// fails ρ₀ (no verdict holds vacuously); γ does not depend on the shape.
void check_lu_bounds(const EnclosedMesh3& m, const Certify3Options& o, Certify3Report& r) {
  const auto& mesh = m.mesh;
  const Rational rho2 = o.rho0 ? *o.rho0 * *o.rho0 : Rational(0), gamma2 = o.gamma0 ? *o.gamma0 * *o.gamma0 : Rational(0);
  const std::optional<double> gamma2_double =
      rational_from_double(approximate(gamma2)) == gamma2 ? std::optional<double>(approximate(gamma2)) : std::nullopt;
  const double rho2_lo = enclose(rho2).lo;
  const auto name = [](const char* what, int k) { return std::string(what) + " " + std::to_string(k); };
  for (std::size_t ti = 0; ti < mesh.tetrahedra.size(); ++ti) {
    const auto& t = mesh.tetrahedra[ti];
    const int tetrahedron = static_cast<int>(ti);
    const bool flat = m.orientation(ti) == Sign::zero;
    if (o.rho0 && flat)  // no circumsphere: the ratio is unbounded, never at most ρ₀
      r.rho_violations.add(t[0], tetrahedron, -1, [&] { return name("tetrahedron", tetrahedron) + " is flat: its radius-edge ratio is unbounded"; });
    if (o.rho0 && !flat)
      for (std::size_t i = 0; i < 4; ++i) {
        const int v = t[i];
        const auto vi = static_cast<std::size_t>(v);
        if (std::any_of(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(i), [&](int u) { return m.same_metric(u, v); }))
          continue;  // the same metric, the same ratio
        const auto at = [&](auto& points, std::size_t k) { return points[static_cast<std::size_t>(t[k])]; };
        const I e = radius_edge_squared(std::array{at(m.vertex, 0), at(m.vertex, 1), at(m.vertex, 2), at(m.vertex, 3)}, m.metric[vi]);
        if (e.hi < rho2_lo) {  // decided by the enclosure: ≤ ρ₀²
          const double approx = std::sqrt((e.lo + e.hi) / 2);
          if (approx > r.worst_rho) r.worst_rho = approx, r.worst_rho_tetrahedron = tetrahedron, r.worst_rho_vertex = v;
          continue;
        }
        const Rational q = radius_edge_squared(std::array{at(mesh.vertices, 0), at(mesh.vertices, 1), at(mesh.vertices, 2), at(mesh.vertices, 3)},
                                               mesh.metrics[vi]);
        const double approx = std::sqrt(q.convert_to<double>());
        if (approx > r.worst_rho) r.worst_rho = approx, r.worst_rho_tetrahedron = tetrahedron, r.worst_rho_vertex = v;
        if (q > rho2) {
          r.rho_violations.add(v, tetrahedron, -1, [&, v, approx] {
            return name("tetrahedron", tetrahedron) + " has radius-edge ratio " + std::to_string(approx) + " > ρ₀ in the metric of " +
                   name("vertex", v);
          });
          break;
        }
      }
    if (o.gamma0)
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
          const int a = t[i], b = t[j];
          const auto &Ma = mesh.metrics[static_cast<std::size_t>(a)], &Mb = mesh.metrics[static_cast<std::size_t>(b)];
          if (Ma == Mb) {  // γ = 1 ≤ γ₀
            if (r.worst_gamma_tetrahedron < 0) r.worst_gamma = 1, r.worst_gamma_tetrahedron = tetrahedron;
            continue;
          }
          const double g = std::sqrt(geometry::tau_squared_estimate(midpoint(m.metric[static_cast<std::size_t>(a)]), midpoint(m.metric[static_cast<std::size_t>(b)])));
          if (g > r.worst_gamma) r.worst_gamma = g, r.worst_gamma_tetrahedron = tetrahedron;
          // Both metrics and γ₀² doubles: the filtered double path (exact, the same answer) spares
          // converting twelve rationals per pair (60% of certifying a refined cube's mesh).
          const bool doubles = gamma2_double && m.exact_metric[static_cast<std::size_t>(a)] && m.exact_metric[static_cast<std::size_t>(b)];
          const bool within = doubles ? predicates::tau_at_most(midpoint(m.metric[static_cast<std::size_t>(a)]),
                                                                 midpoint(m.metric[static_cast<std::size_t>(b)]), *gamma2_double)
                                      : predicates::tau_at_most(Ma, Mb, gamma2);
          if (!within) {
            r.gamma_violations.add(a, tetrahedron, b, [&, a, b, g] {
              return name("tetrahedron", tetrahedron) + ": distortion between vertices " + std::to_string(a) + " and " + std::to_string(b) +
                     " is about " + std::to_string(g) + " > γ₀";
            });
            i = j = 4;  // one witness per tetrahedron
          }
        }
  }
}

// Whether vertex p is certainly outside the enclosed ellipsoid: (p − c)ᵀ M (p − c) > r² on the
// enclosures. Then the exact in-sphere sign is "outside" too; the filter only spares the lifted
// 4 × 4 determinant for the many candidates of the box that the ellipsoid does not reach.
bool certainly_outside(const Ellipsoid& e, const predicates::Point3<I>& p, const predicates::Sym3<I>& M) {
  const std::array<I, 3> d{p.x - e.centre[0], p.y - e.centre[1], p.z - e.centre[2]};
  const auto Md = times(M, d);
  return (d[0] * Md[0] + d[1] * Md[1] + d[2] * Md[2]).lo > e.r2.hi;
}

// The inputs of the in-sphere test of e against t in the metric of v when all are doubles.
std::optional<std::array<double, 21>> double_inputs(const EnclosedMesh3& m, const std::array<int, 4>& t, int e, int v) {
  const std::array<int, 5> idx{t[0], t[1], t[2], t[3], e};
  if (!m.doubles(idx, v)) return std::nullopt;
  std::array<double, 21> x;
  for (std::size_t k = 0; k < 5; ++k) {
    const auto& p = m.approx[static_cast<std::size_t>(idx[k])];
    x[3 * k] = p.x, x[3 * k + 1] = p.y, x[3 * k + 2] = p.z;
  }
  const auto& N = m.metric[static_cast<std::size_t>(v)];  // point enclosures: lo is the value
  x[15] = N.m11.lo, x[16] = N.m12.lo, x[17] = N.m13.lo, x[18] = N.m22.lo, x[19] = N.m23.lo, x[20] = N.m33.lo;
  return x;
}

// sign of the in-sphere test of e against tetrahedron t in the metric of vertex v: the filtered
// predicate on doubles when every input is one, else intervals first.
Sign insphere(const EnclosedMesh3& m, const std::array<int, 4>& t, int e, int v) {
  if (const auto x = double_inputs(m, t, e, v)) return predicates::filtered_sign<predicates::InSphereKernel>(*x);
  const std::array<int, 5> idx{t[0], t[1], t[2], t[3], e};
  const auto& P = m.vertex;
  const auto& M = m.metric[static_cast<std::size_t>(v)];
  std::array<FilterInterval, 21> in;
  for (std::size_t k = 0; k < 5; ++k) {
    const auto& p = P[static_cast<std::size_t>(idx[k])];
    in[3 * k] = p.x, in[3 * k + 1] = p.y, in[3 * k + 2] = p.z;
  }
  in[15] = M.m11, in[16] = M.m12, in[17] = M.m13, in[18] = M.m22, in[19] = M.m23, in[20] = M.m33;
  return predicates::interval_then_exact<predicates::InSphereKernel>(in, [&] {
    const auto& X = m.mesh.vertices;
    const auto& N = m.mesh.metrics[static_cast<std::size_t>(v)];
    std::array<Rational, 21> q;
    for (std::size_t k = 0; k < 5; ++k) {
      const auto& p = X[static_cast<std::size_t>(idx[k])];
      q[3 * k] = p.x, q[3 * k + 1] = p.y, q[3 * k + 2] = p.z;
    }
    q[15] = N.m11, q[16] = N.m12, q[17] = N.m13, q[18] = N.m22, q[19] = N.m23, q[20] = N.m33;
    return q;
  });
}

// What the search of one tetrahedron found: one witness per tetrahedron, as in 2D
// (mesh_certifier.cpp): the search stops at the first vertex strictly inside (`violation`), and
// records one tie at most (`tie`, found before any violation); vertex −1 where none.
struct UniformResult3 {
  struct Found {
    int vertex = -1, inside = -1;  // the metric's vertex, the vertex inside (or on) the sphere
  };
  Found tie, violation;
  std::size_t insphere_tests = 0;
  bool unmeasured = false;  // flat
};

// The search of tetrahedron ti in each of its vertices' metrics: the candidates in the box of its
// circumellipsoid enclosed (every vertex when the enclosure fails), each decided exactly.
UniformResult3 search(const EnclosedMesh3& m, const VertexGrid& grid, const std::vector<std::optional<std::array<I, 3>>>& diagonals,
                      std::size_t ti) {
  thread_local std::vector<int> candidates;
  UniformResult3 u;
  const auto& t = m.mesh.tetrahedra[ti];
  const Sign orientation = m.orientation(ti);
  if (orientation == Sign::zero) {
    u.unmeasured = true;
    return u;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    const int v = t[i];
    // A metric equal to an earlier vertex's (a constant field) asks the same question again.
    const auto same = [&](std::size_t j) { return m.same_metric(t[j], v); };
    if ((i > 0 && same(0)) || (i > 1 && same(1)) || (i > 2 && same(2))) continue;
    const auto& Mv = m.metric[static_cast<std::size_t>(v)];
    const auto ellipsoid = enclose_ellipsoid(m, t, v, diagonals[static_cast<std::size_t>(v)]);
    if (ellipsoid) {
      grid.query(ellipsoid->lo, ellipsoid->hi, candidates);
    } else {
      candidates.resize(m.mesh.vertices.size());
      for (std::size_t k = 0; k < candidates.size(); ++k) candidates[k] = static_cast<int>(k);
    }
    // With doubles only, the static in-sphere filter first (cheaper than the interval sphere
    // test); when it cannot decide (nearly cospherical), the sphere test before the exact path.
    // Its inputs but the candidate's, once.
    const bool doubles = m.doubles(t, v);
    std::array<double, 21> x;
    if (doubles) x = *double_inputs(m, t, t[0], v);
    for (const int e : candidates) {
      if (e == t[0] || e == t[1] || e == t[2] || e == t[3]) continue;
      std::optional<Sign> quick;
      if (doubles && m.exact[static_cast<std::size_t>(e)]) {
        const auto& p = m.approx[static_cast<std::size_t>(e)];
        x[12] = p.x, x[13] = p.y, x[14] = p.z;
        quick = predicates::static_sign<predicates::InSphereKernel, predicates::static_error_model<predicates::InSphereKernel>>(x);
      }
      if (!quick && ellipsoid && certainly_outside(*ellipsoid, m.vertex[static_cast<std::size_t>(e)], Mv)) continue;
      ++u.insphere_tests;
      const Sign s = (quick ? *quick : insphere(m, t, e, v)) * orientation;
      if (s == Sign::negative || (s == Sign::zero && u.tie.vertex >= 0)) continue;
      if (s == Sign::positive) {
        u.violation = {v, e};
        return u;
      }
      u.tie = {v, e};
    }
  }
  return u;
}

// The edges (u, v), u < v, in increasing order: bucketed by u (a counting sort), each bucket's
// few ends sorted and made unique; the same list as sorting all 6 per tetrahedron, in linear time.
std::vector<std::pair<int, int>> unique_edges(const std::vector<std::array<int, 4>>& tets, std::size_t vertices) {
  std::vector<std::size_t> start(vertices + 1, 0);
  for (const auto& t : tets)
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) ++start[static_cast<std::size_t>(std::min(t[i], t[j])) + 1];
  for (std::size_t u = 1; u <= vertices; ++u) start[u] += start[u - 1];
  std::vector<int> other(start[vertices]);
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const auto& t : tets)
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) other[next[static_cast<std::size_t>(std::min(t[i], t[j]))]++] = std::max(t[i], t[j]);
  std::vector<std::pair<int, int>> e;
  e.reserve(other.size() / 4);
  for (std::size_t u = 0; u < vertices; ++u) {
    const auto first = other.begin() + static_cast<std::ptrdiff_t>(start[u]), last = other.begin() + static_cast<std::ptrdiff_t>(start[u + 1]);
    std::sort(first, last);
    for (auto it = first; it != last; it = std::upper_bound(it, last, *it)) e.emplace_back(static_cast<int>(u), *it);
  }
  return e;
}

// The locally uniform search on every thread, its findings added in tetrahedron order: the report
// does not depend on the number of threads.
void check_uniform(const EnclosedMesh3& m, int threads, Certify3Report& r) {
  const auto& mesh = m.mesh;
  r.uniform_checked = true;
  const VertexGrid grid(m.approx);
  std::vector<std::optional<std::array<I, 3>>> diagonals(mesh.vertices.size());
  for (std::size_t v = 0; v < diagonals.size(); ++v) diagonals[v] = inverse_diagonal(m.metric[v]);
  const auto compute = [&](std::size_t t) { return search(m, grid, diagonals, t); };
  parallel_in_order(mesh.tetrahedra.size(), thread_count(threads), compute, [&](std::size_t t, const UniformResult3& u) {
    r.unmeasured += u.unmeasured ? 1 : 0;
    r.insphere_tests += u.insphere_tests;
    const int tetrahedron = static_cast<int>(t);
    for (const auto& [f, strict] : {std::pair{u.tie, false}, std::pair{u.violation, true}}) {
      if (f.vertex < 0) continue;
      const UniformResult3::Found found = f;  // named, not bound: clang 14 cannot capture bindings
      (strict ? r.uniform_violations : r.uniform_ties).add(found.vertex, tetrahedron, found.inside, [&, strict = strict] {
        return "vertex " + std::to_string(found.inside) + " is " + (strict ? "strictly inside" : "on") + " the circumsphere of tetrahedron " +
               std::to_string(tetrahedron) + " in the metric of its vertex " + std::to_string(found.vertex);
      });
    }
  });
}

}  // namespace

Certify3Report certify_mesh3(const geometry::Mesh3<Rational>& mesh, const Certify3Options& o) {
  const EnclosedMesh3 m(mesh);
  Certify3Report r;
  r.tetrahedra = mesh.tetrahedra.size();
  r.uniform_violations = WitnessList(o.described_witnesses);
  r.uniform_ties = WitnessList(o.described_witnesses);
  r.rho_violations = WitnessList(o.described_witnesses);
  r.gamma_violations = WitnessList(o.described_witnesses);
  const bool has_metrics = mesh.metrics.size() == mesh.vertices.size() && !mesh.metrics.empty();
  const int threads = thread_count(o.threads);
  // The per-element checks on a thread of their own beside the locally uniform search and the
  // sliver measure, which run on every thread: they write different parts of the report.
  concurrently(
      threads,
      [&] {
        if (o.valid) r.valid = check_tetrahedralization(m, o.described_witnesses);
        if ((o.rho0 || o.gamma0) && has_metrics) check_lu_bounds(m, o, r);
        if (o.metric && has_metrics) {
          const std::vector<std::pair<int, int>> edges = unique_edges(mesh.tetrahedra, mesh.vertices.size());
          r.lengths = check_lengths(m, edges, o.length_range, o.described_witnesses);
          r.quality = check_quality(m, o.min_quality, o.described_witnesses);
          r.angles = check_angles(m, o.min_angle, o.described_witnesses);
          r.ugawg = ugawg_measures(m, edges, r.valid && r.valid->orientation == "negative" ? -1 : 1);
        }
      },
      [&] {
        if (!o.uniform || !has_metrics) return;
        check_uniform(m, threads, r);
        r.cosphericity = check_quasi_cosphericity(m, o.gamma0, o.described_witnesses, threads);
      });
  return r;
}

}  // namespace anisocert::oracle
