#include "oracle/certify/enclosed_mesh.hpp"

#include "predicates/orientation.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace anisocert::oracle {
namespace {

struct EndsHash {
  std::size_t operator()(const std::array<double, 12>& a) const {
    std::size_t h = 0;
    for (const double x : a) h = h * 1000003u ^ std::hash<double>{}(x);
    return h;
  }
};

// The tightest enclosure of q given d = approximate(q).
FilterInterval enclose(const Rational& q, double d) {
  // q is a normal double (or 0) when its reduced numerator has at most 53 bits and its
  // denominator is 2^e with e <= 1022: then the conversion was exact. No allocation.
  const mpz_srcptr num = mpq_numref(q.backend().data()), den = mpq_denref(q.backend().data());
  const std::size_t e = mpz_scan1(den, 0);
  if (e + 1 == mpz_sizeinbase(den, 2) && e <= 1022 && mpz_sizeinbase(num, 2) <= 53) return {d, d};
  return FilterInterval::widen(d, d);  // within an ulp (approximate's rounding towards zero)
}

}  // namespace

double approximate(const Rational& q) { return mpq_get_d(q.backend().data()); }

FilterInterval enclose(const Rational& q) { return enclose(q, approximate(q)); }

predicates::Sym3<double> midpoint(const predicates::Sym3<FilterInterval>& M) {
  const auto mid = [](const FilterInterval& x) { return x.lo / 2 + x.hi / 2; };
  return {mid(M.m11), mid(M.m12), mid(M.m13), mid(M.m22), mid(M.m23), mid(M.m33)};
}

EnclosedMesh::EnclosedMesh(const geometry::Mesh<Rational>& m) : mesh(m) {
  site.reserve(m.sites.size());
  approx.reserve(m.sites.size());
  for (const auto& p : m.sites) {
    site.push_back({enclose(p.x), enclose(p.y)});
    approx.push_back({approximate(p.x), approximate(p.y)});
  }
  metric.reserve(m.metrics.size());
  for (const auto& M : m.metrics) metric.push_back({enclose(M.m11), enclose(M.m12), enclose(M.m22)});
}

Sign EnclosedMesh::orientation(int a, int b, int c) const {
  const auto &pa = site[a], &pb = site[b], &pc = site[c];
  return predicates::interval_then_exact<predicates::OrientationKernel>(
      std::array<FilterInterval, 6>{pa.x, pa.y, pb.x, pb.y, pc.x, pc.y}, [&] {
        const auto& s = mesh.sites;
        return std::array<Rational, 6>{s[a].x, s[a].y, s[b].x, s[b].y, s[c].x, s[c].y};
      });
}

EnclosedMesh3::EnclosedMesh3(const geometry::Mesh3<Rational>& m) : mesh(m) {
  vertex.reserve(m.vertices.size());
  approx.reserve(m.vertices.size());
  exact.reserve(m.vertices.size());
  for (const auto& p : m.vertices) {
    approx.push_back({approximate(p.x), approximate(p.y), approximate(p.z)});
    const auto& a = approx.back();
    vertex.push_back({enclose(p.x, a.x), enclose(p.y, a.y), enclose(p.z, a.z)});
    const auto& v = vertex.back();
    exact.push_back(v.x.lo == v.x.hi && v.y.lo == v.y.hi && v.z.lo == v.z.hi);
  }
  metric.reserve(m.metrics.size());
  exact_metric.reserve(m.metrics.size());
  for (const auto& M : m.metrics) {
    metric.push_back({enclose(M.m11), enclose(M.m12), enclose(M.m13), enclose(M.m22), enclose(M.m23), enclose(M.m33)});
    const auto& e = metric.back();
    exact_metric.push_back(e.m11.lo == e.m11.hi && e.m12.lo == e.m12.hi && e.m13.lo == e.m13.hi && e.m22.lo == e.m22.hi &&
                           e.m23.lo == e.m23.hi && e.m33.lo == e.m33.hi);
  }
  // Classes of equal metrics: candidates share their enclosures' twelve ends; equal exactly.
  std::unordered_map<std::array<double, 12>, std::vector<int>, EndsHash> representatives;
  metric_class.reserve(metric.size());
  for (std::size_t i = 0; i < metric.size(); ++i) {
    const auto& e = metric[i];
    auto& bucket = representatives[{e.m11.lo, e.m11.hi, e.m12.lo, e.m12.hi, e.m13.lo, e.m13.hi, e.m22.lo, e.m22.hi, e.m23.lo, e.m23.hi, e.m33.lo, e.m33.hi}];
    const auto same = std::find_if(bucket.begin(), bucket.end(), [&](int r) { return m.metrics[static_cast<std::size_t>(r)] == m.metrics[i]; });
    if (same != bucket.end()) {
      metric_class.push_back(metric_class[static_cast<std::size_t>(*same)]);
    } else {
      metric_class.push_back(static_cast<int>(i));
      bucket.push_back(static_cast<int>(i));
    }
  }
  orientations.reserve(m.tetrahedra.size());
  for (const auto& t : m.tetrahedra) orientations.push_back(orientation(t[0], t[1], t[2], t[3]));
  faces = faces_in_order(m.tetrahedra, m.vertices.size());
}

Sign EnclosedMesh3::orientation(int a, int b, int c, int d) const {
  if (exact[a] && exact[b] && exact[c] && exact[d]) {  // the approximations are the exact doubles
    const auto &pa = approx[a], &pb = approx[b], &pc = approx[c], &pd = approx[d];
    return predicates::filtered_sign<predicates::Orientation3Kernel>(
        std::array<double, 12>{pa.x, pa.y, pa.z, pb.x, pb.y, pb.z, pc.x, pc.y, pc.z, pd.x, pd.y, pd.z});
  }
  const auto &pa = vertex[a], &pb = vertex[b], &pc = vertex[c], &pd = vertex[d];
  return predicates::interval_then_exact<predicates::Orientation3Kernel>(
      std::array<FilterInterval, 12>{pa.x, pa.y, pa.z, pb.x, pb.y, pb.z, pc.x, pc.y, pc.z, pd.x, pd.y, pd.z}, [&] {
        const auto& v = mesh.vertices;
        return std::array<Rational, 12>{v[a].x, v[a].y, v[a].z, v[b].x, v[b].y, v[b].z, v[c].x, v[c].y, v[c].z, v[d].x, v[d].y, v[d].z};
      });
}

}  // namespace anisocert::oracle
