#include "oracle/certify/quasi_cosphericity.hpp"

#include "geometry/circumellipsoid.hpp"
#include "oracle/parallel_for.hpp"
#include "predicates/quasi_cospherical.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <type_traits>

namespace anisocert::oracle {
namespace {

// Two tetrahedra sharing a face: the face's three vertices, the opposite vertex of each.
struct Configuration {
  std::array<int, 5> vertex;  // a, b, c, d, e: abc shared, d in the first, e in the second
  std::array<int, 2> tetrahedron;
};

// The faces in exactly two tetrahedra (validity reports the others): the index in m.faces of the
// first of each pair.
std::vector<std::size_t> shared_faces(const EnclosedMesh3& m) {
  const auto& faces = m.faces;
  std::vector<std::size_t> first;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j].sorted == faces[i].sorted) ++j;
    if (j == i + 2) first.push_back(i);
    i = j;
  }
  return first;
}

// The configuration of the face pair m.faces[i], m.faces[i + 1].
Configuration configuration(const EnclosedMesh3& m, std::size_t i) {
  const TetrahedronFace &f = m.faces[i], &g = m.faces[i + 1];
  const auto opposite = [&](const TetrahedronFace& h) {
    return m.mesh.tetrahedra[static_cast<std::size_t>(h.tetrahedron)][static_cast<std::size_t>(h.opposite)];
  };
  return {{f.sorted[0], f.sorted[1], f.sorted[2], opposite(f), opposite(g)}, {f.tetrahedron, g.tetrahedron}};
}

// γ* from c₁ = tr GM, c₂, c₃ (the eigenvalues of GM by the trigonometric solution of the cubic,
// all real) and c₁'s exact sign s: (Σ h⁺ / Σ |h⁻|)^(1/4) with c₁ made positive by s (not by its
// approximation, whose sign a nearly cospherical configuration may get wrong), at least 1 as γ*
// is; +∞ when no eigenvalue is negative, NaN beyond the doubles.
double critical_distortion(double c1, double c2, double c3, Sign s) {
  if (s == Sign::negative) c1 = -c1, c3 = -c3;
  const double shift = c1 / 3, p = c2 - c1 * c1 / 3, q = -2 * c1 * c1 * c1 / 27 + c1 * c2 / 3 - c3;
  std::array<double, 3> h{shift, shift, shift};
  if (p < 0) {
    // h_k = shift + r cos(θ − 2πk/3), k = 0, 1, 2, from one cosine and one sine of θ.
    const double r = 2 * std::sqrt(-p / 3), cosine = std::clamp(3 * q / (p * r), -1.0, 1.0), theta = std::acos(cosine) / 3;
    const double c = r * std::cos(theta), s = r * std::sin(theta) * std::numbers::sqrt3 / 2;
    h = {shift + c, shift - c / 2 + s, shift - c / 2 - s};
  }
  double positive = 0, negative = 0;
  for (const double x : h) (x > 0 ? positive : negative) += std::abs(x);
  if (!std::isfinite(positive) || !std::isfinite(negative)) return NAN;
  return negative > 0 ? std::max(1.0, std::sqrt(std::sqrt(positive / negative))) : INFINITY;
}

// LU Definition 3.9's radius-edge ratio of five points in metric M, in doubles: the least
// M-circumradius of a non-flat four-point subset over the shortest M-distance.
double radius_edge_ratio(const std::array<predicates::Point3<double>, 5>& p, const predicates::Sym3<double>& M) {
  double r2 = INFINITY, d2 = INFINITY;
  for (std::size_t skip = 0; skip < 5; ++skip) {
    std::array<predicates::Point3<double>, 4> q;
    for (std::size_t i = 0, j = 0; i < 5; ++i)
      if (i != skip) q[j++] = p[i];
    const double r = geometry::circumellipsoid(q[0], q[1], q[2], q[3], M).r2;
    if (std::isfinite(r) && r > 0) r2 = std::min(r2, r);
  }
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = i + 1; j < 5; ++j) d2 = std::min(d2, predicates::quadratic_form(M, p[j].x - p[i].x, p[j].y - p[i].y, p[j].z - p[i].z));
  return std::sqrt(r2 / d2);
}

// What the measure of one configuration found, for the report (in configuration order).
struct ConfigurationResult {
  bool flat = false;  // a flat tetrahedron: not a configuration
  double least = INFINITY;  // γ*, the least over the five metrics
  // `counted`: γ₀-cospherical in some metric (decided strictly); `boundary`: exactly at γ₀ in
  // some metric, which counts only when no metric makes it strict.
  bool counted = false, boundary = false, measured = true, exactly = false;
  struct {
    int vertex = -1;  // the metric's, where counted
    double critical = 0, ratio = 0;
  } witness;
};

// Configuration c in each of its vertices' metrics; k = γ₀⁴ − 1 and its enclosure ki.
ConfigurationResult measure(const EnclosedMesh3& m, const Configuration& c, const std::optional<Rational>& gamma0, const Rational& k,
                            const FilterInterval& ki) {
  const auto& mesh = m.mesh;
  ConfigurationResult u;
  if (m.orientation(static_cast<std::size_t>(c.tetrahedron[0])) == Sign::zero || m.orientation(static_cast<std::size_t>(c.tetrahedron[1])) == Sign::zero) {
    u.flat = true;
    return u;
  }
  std::array<FilterInterval, 22> xi;
  std::array<predicates::Point3<double>, 5> approx;
  for (std::size_t i = 0; i < 5; ++i) {
    const auto vi = static_cast<std::size_t>(c.vertex[i]);
    const auto& p = m.vertex[vi];
    xi[3 * i] = p.x, xi[3 * i + 1] = p.y, xi[3 * i + 2] = p.z;
    approx[i] = m.approx[vi];
  }
  xi[21] = ki;
  for (std::size_t i = 0; i < 5; ++i) {
    const int v = c.vertex[i];
    if (std::any_of(c.vertex.begin(), c.vertex.begin() + static_cast<std::ptrdiff_t>(i), [&](int w) { return m.same_metric(w, v); })) continue;
    const auto& M = m.metric[static_cast<std::size_t>(v)];
    xi[15] = M.m11, xi[16] = M.m12, xi[17] = M.m13, xi[18] = M.m22, xi[19] = M.m23, xi[20] = M.m33;
    // The sign of kernel K on this configuration in M_v: with doubles only (point enclosures),
    // the double evaluation checked for rounding, intervals, then expansions (a lattice's zeros
    // are decided at the first); else intervals, then rationals.
    const auto sign_of = [&]<class K>(K) {
      std::array<FilterInterval, K::arity> in;
      for (std::size_t j = 0; j < K::arity; ++j) in[j] = xi[j];
      if (std::all_of(in.begin(), in.end(), [](const FilterInterval& e) { return e.lo == e.hi; })) {
        std::array<double, K::arity> d;
        for (std::size_t j = 0; j < K::arity; ++j) d[j] = in[j].lo;
        return predicates::filtered_sign_slow<K>(d);
      }
      return predicates::interval_then_exact<K>(in, [&] {
        std::array<Rational, K::arity> q;
        for (std::size_t j = 0; j < 5 && 3 * j < K::arity; ++j) {
          const auto& p = mesh.vertices[static_cast<std::size_t>(c.vertex[j])];
          q[3 * j] = p.x, q[3 * j + 1] = p.y, q[3 * j + 2] = p.z;
        }
        const auto& N = mesh.metrics[static_cast<std::size_t>(v)];
        q[15] = N.m11, q[16] = N.m12, q[17] = N.m13, q[18] = N.m22, q[19] = N.m23, q[20] = N.m33;
        if constexpr (K::arity == 22) q[21] = k;
        return q;
      });
    };
    // e on the M_v-sphere: the static filter when every input is a double, else as the others.
    const bool doubles = m.doubles(c.vertex, v);
    std::array<double, 21> x;
    for (std::size_t j = 0; j < 5; ++j) x[3 * j] = approx[j].x, x[3 * j + 1] = approx[j].y, x[3 * j + 2] = approx[j].z;
    const auto Md = midpoint(M);
    x[15] = Md.m11, x[16] = Md.m12, x[17] = Md.m13, x[18] = Md.m22, x[19] = Md.m23, x[20] = Md.m33;
    const Sign on = doubles ? predicates::filtered_sign<predicates::InSphereKernel>(x) : sign_of(predicates::InSphereKernel{});
    double critical = 1;
    if (on == Sign::zero) {
      u.exactly = true;
    } else {
      const auto [c2, c3] = predicates::lifted_gram_invariants(x);
      critical = critical_distortion(predicates::InSphereKernel::eval(x), c2, c3, on);
    }
    if (std::isnan(critical)) u.measured = false;
    else u.least = std::min(u.least, critical);
    if (!gamma0 || u.counted) continue;
    // The kernels share G: its invariants enclosed once, each kernel's sign read off them when
    // they decide it (an enclosure of the same polynomial), else the kernel's own evaluation.
    std::array<FilterInterval, 21> x21;
    for (std::size_t j = 0; j < 21; ++j) x21[j] = xi[j];
    const FilterInterval c1 = predicates::InSphereKernel::eval(x21);
    const auto [c2, c3] = predicates::lifted_gram_invariants(x21);
    const FilterInterval A = predicates::one_negative_polynomial(c1, c2, c3, ki), B = predicates::two_negative_polynomial(c1, c2, c3, ki);
    const auto shared_sign = [&, c2 = c2, c3 = c3]<class K>(K kernel) {
      std::optional<Sign> known;
      if constexpr (std::is_same_v<K, predicates::InSphereKernel>) known = c1.sign();
      if constexpr (std::is_same_v<K, predicates::LiftedGramSecondKernel>) known = c2.sign();
      if constexpr (std::is_same_v<K, predicates::LiftedGramThirdKernel>) known = c3.sign();
      if constexpr (std::is_same_v<K, predicates::CosphericalOneNegativeKernel>) known = A.sign();
      if constexpr (std::is_same_v<K, predicates::CosphericalTwoNegativeKernel>) known = B.sign();
      return known ? *known : sign_of(kernel);
    };
    const Sign s = predicates::quasi_cospherical_from(shared_sign);
    if (s == Sign::negative) continue;
    if (s == Sign::zero) {
      u.boundary = true;
      continue;
    }
    u.counted = true;
    u.witness = {v, critical, radius_edge_ratio(approx, Md)};
  }
  return u;
}

}  // namespace

CosphericityReport check_quasi_cosphericity(const EnclosedMesh3& m, const std::optional<Rational>& gamma0, std::size_t described, int threads) {
  CosphericityReport r;
  r.witnesses = WitnessList(described);
  r.decided = gamma0.has_value();
  const Rational k = gamma0 ? *gamma0 * *gamma0 * *gamma0 * *gamma0 - 1 : Rational(0);
  const FilterInterval ki = enclose(k);
  const std::vector<std::size_t> pairs = shared_faces(m);
  const auto compute = [&](std::size_t i) { return measure(m, configuration(m, pairs[i]), gamma0, k, ki); };
  // In configuration order: the report does not depend on the number of threads.
  parallel_in_order(pairs.size(), thread_count(threads), compute, [&](std::size_t i, const ConfigurationResult& u) {
    const Configuration c = configuration(m, pairs[i]);
    if (u.flat) return;
    ++r.configurations;
    if (u.counted) {
      ++r.quasi_cospherical;
      const auto& w = u.witness;
      if (w.ratio < r.least_radius_edge) r.least_radius_edge = w.ratio, r.least_radius_edge_tetrahedra[0] = c.tetrahedron[0], r.least_radius_edge_tetrahedra[1] = c.tetrahedron[1];
      r.witnesses.add(w.vertex, c.tetrahedron[0], c.tetrahedron[1], [&] {
        return "tetrahedra " + std::to_string(c.tetrahedron[0]) + " and " + std::to_string(c.tetrahedron[1]) + " (vertices " +
               std::to_string(c.vertex[0]) + " " + std::to_string(c.vertex[1]) + " " + std::to_string(c.vertex[2]) + " " +
               std::to_string(c.vertex[3]) + " " + std::to_string(c.vertex[4]) + ") are γ₀-cospherical in the metric of vertex " +
               std::to_string(w.vertex) + " (critical distortion about " + std::to_string(w.critical) + ", radius-edge ratio about " +
               std::to_string(w.ratio) + ")";
      });
    }
    if (u.boundary && !u.counted) ++r.at_boundary;
    if (!u.measured) ++r.unmeasured;
    if (u.exactly) ++r.cospherical;
    if (u.least < r.least_critical) r.least_critical = u.least, r.least_tetrahedra[0] = c.tetrahedron[0], r.least_tetrahedra[1] = c.tetrahedron[1];
  });
  return r;
}

}  // namespace anisocert::oracle
