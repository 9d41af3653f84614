#include "oracle/certify/ugawg_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::oracle {
namespace {

using predicates::Point3;
using predicates::Sym3;

double det(const Sym3<double>& M) {
  return M.m11 * (M.m22 * M.m33 - M.m23 * M.m23) - M.m12 * (M.m12 * M.m33 - M.m23 * M.m13) + M.m13 * (M.m12 * M.m23 - M.m22 * M.m13);
}

double length2(const Sym3<double>& M, const Point3<double>& a, const Point3<double>& b) {
  const double x = b.x - a.x, y = b.y - a.y, z = b.z - a.z;
  return M.m11 * x * x + M.m22 * y * y + M.m33 * z * z + 2 * (M.m12 * x * y + M.m13 * x * z + M.m23 * y * z);
}

}  // namespace

double log_interpolated_length(double la, double lb) {
  if (la == lb) return la;
  return (la - lb) / std::log(la / lb);
}

double omega_h_quality(const std::array<Point3<double>, 4>& p, const Sym3<double>& M) {
  const double ux = p[1].x - p[0].x, uy = p[1].y - p[0].y, uz = p[1].z - p[0].z;
  const double vx = p[2].x - p[0].x, vy = p[2].y - p[0].y, vz = p[2].z - p[0].z;
  const double wx = p[3].x - p[0].x, wy = p[3].y - p[0].y, wz = p[3].z - p[0].z;
  const double D = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  const double volume = std::sqrt(std::max(0.0, det(M))) * std::abs(D) / 6;
  double S = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) S += length2(M, p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]);
  if (S <= 0) return 0;
  const double q = 12 * std::cbrt(9 * volume * volume) / S;  // 12 (3V)^(2/3) / S
  return D < 0 ? -q : q;
}

UgawgMeasures ugawg_measures(const EnclosedMesh3& m, const std::vector<std::pair<int, int>>& edges, int orientation) {
  UgawgMeasures r;
  std::vector<Sym3<double>> metric;
  metric.reserve(m.metric.size());
  for (const auto& M : m.metric) metric.push_back(midpoint(M));
  r.shortest = std::numeric_limits<double>::infinity(), r.longest = 0;
  double sum = 0;
  const double lo = 1 / std::sqrt(2.0), hi = std::sqrt(2.0);
  for (const auto& [a, b] : edges) {
    const auto& pa = m.approx[static_cast<std::size_t>(a)];
    const auto& pb = m.approx[static_cast<std::size_t>(b)];
    const double l = log_interpolated_length(std::sqrt(length2(metric[static_cast<std::size_t>(a)], pa, pb)),
                                             std::sqrt(length2(metric[static_cast<std::size_t>(b)], pa, pb)));
    if (!std::isfinite(l)) {  // beyond the doubles (coordinates near 1e155 overflow)
      ++r.unmeasured;
      continue;
    }
    r.shortest = std::min(r.shortest, l), r.longest = std::max(r.longest, l), sum += l;
    r.unit_edges += l >= lo && l <= hi;
  }
  r.edges = edges.size();
  const std::size_t unmeasured_edges = r.unmeasured, lengths = edges.size() - unmeasured_edges;
  r.mean_length = lengths == 0 ? 0 : sum / static_cast<double>(lengths);
  if (lengths == 0) r.shortest = 0;
  const auto& tets = m.mesh.tetrahedra;
  r.tetrahedra = tets.size();
  r.least_quality = std::numeric_limits<double>::infinity();
  double qsum = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    std::array<Point3<double>, 4> p;
    std::size_t maxdet = static_cast<std::size_t>(tets[t][0]);
    for (std::size_t i = 0; i < 4; ++i) {
      const auto v = static_cast<std::size_t>(tets[t][i]);
      p[i] = m.approx[v];
      if (det(metric[v]) > det(metric[maxdet])) maxdet = v;
    }
    const double q = (orientation < 0 ? -1 : 1) * omega_h_quality(p, metric[maxdet]);
    if (!std::isfinite(q)) {
      ++r.unmeasured;
      continue;
    }
    if (q < r.least_quality) r.least_quality = q, r.least_tetrahedron = t;
    qsum += q;
    ++r.quality_bins[static_cast<std::size_t>(std::clamp(q * 10, 0.0, 9.0))];
  }
  const std::size_t qualities = tets.size() - (r.unmeasured - unmeasured_edges);
  r.mean_quality = qualities == 0 ? 0 : qsum / static_cast<double>(qualities);
  if (qualities == 0) r.least_quality = 0;
  return r;
}

}  // namespace anisocert::oracle
