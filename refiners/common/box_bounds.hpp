#pragma once
// Bounds over a box of a site's squared distance d_u(p)² = (p − u)ᵀM_u(p − u), and of the
// difference of two sites', for the subdivision's candidates (vertex_subdivision.hpp): its hot path,
// so computed in doubles with one rounding bound at the end instead of an interval per operation.
//
// Centred form about the box's midpoint m, p = m + δ, |δ_x| ≤ h_x, |δ_y| ≤ h_y:
//   d_u(m + δ)² = Q + 2gᵀδ + δᵀMδ,  g = M(m − u),  Q = (m − u)ᵀg,
// so Q − 2(|g_x|h_x + |g_y|h_y) − q ≤ d² ≤ Q + 2(|g_x|h_x + |g_y|h_y) + q, q = |M₁₁|h_x² + 2|M₁₂|h_xh_y + |M₂₂|h_y²,
// for any symmetric M; when M is certainly positive semi-definite (checked with a margin, as the
// sites' metrics are), δᵀMδ ≥ 0 and d² ≥ 0 give the lower bound max(0, Q − 2(|g_x|h_x + |g_y|h_y)).
//
// Rounding (N. Higham, Accuracy and Stability of Numerical Algorithms, §3.1): every term is a
// product computed, with the sums it goes through, in at most 9 roundings (the half-widths, rounded
// to nearest, count as one), each within a relative ε = 2⁻⁵³ when nothing underflows; so each end
// is within γ₉ = 9ε/(1 − 9ε) < 2⁻⁴⁹ times S, the same sums with every term replaced by its absolute
// value (S itself computed within the same relative error), and it is moved outward by 2⁻⁴⁵·S,
// sixteen times that. Underflow: each of the few dozen roundings loses at most 2⁻¹⁰⁷⁵, which later
// products multiply by at most T², T = 1 + the largest magnitude among the metric's entries, m − u
// and the half-widths; the ends move by 2⁻¹⁰⁰⁰·T² more. An infinite or NaN value gives no bound:
// [0, ∞] for a squared distance, [−∞, ∞] for a difference.
// `BoxBounds.HoldEveryExactValueInTheBox` checks both bounds against rationals.
#include "refiners/common/domain.hpp"
#include "refiners/common/distance_function.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace anisocert::refiners::common {

struct Bounds {
  double lo, hi;
};

namespace box_bounds_detail {

struct Centre {
  double mx, my, hx, hy;  // the midpoint, and half-widths (rounded to nearest, counted in the bound)
  explicit Centre(const Box& b)
      : mx(b.x0 / 2 + b.x1 / 2), my(b.y0 / 2 + b.y1 / 2), hx(std::max(b.x1 - mx, mx - b.x0)), hy(std::max(b.y1 - my, my - b.y0)) {}
};

inline double largest(std::initializer_list<double> magnitudes) {
  double t = 1;
  for (double m : magnitudes) t = std::max(t, 1 + std::abs(m));
  return t;
}

inline Bounds outward(double lo, double hi, double S, double T, double least) {
  const double e = 0x1p-45 * S + 0x1p-1000 * (T * T);
  lo -= e, hi += e;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {least, std::numeric_limits<double>::infinity()};
  return {lo, hi};
}

// Certainly positive semi-definite: m11, m22 > 0 and m12² ≤ m11·m22, with a margin for rounding,
// and no underflow in the products.
inline bool semi_definite(const Sym2<double>& M) {
  const double p = M.m11 * M.m22;
  return M.m11 > 0 && M.m22 > 0 && p >= 0x1p-900 && M.m12 * M.m12 <= p * (1 - 0x1p-48);
}

}  // namespace box_bounds_detail

// d_u(p)² for every p in b lies in the bounds (the lower one is at least 0 when M_u is certainly
// positive semi-definite).
inline Bounds squared_distance_bounds(const MetricSite& u, const Box& b) {
  using namespace box_bounds_detail;
  const Centre c(b);
  const double ex = c.mx - u.p.x, ey = c.my - u.p.y;
  const double a = u.M.m11, m = u.M.m12, d = u.M.m22;
  const double gx = a * ex + m * ey, gy = m * ex + d * ey;
  const double Q = ex * gx + ey * gy;
  const double linear = 2 * (std::abs(gx) * c.hx + std::abs(gy) * c.hy);
  const double cross = 2 * std::abs(m) * (c.hx * c.hy);
  const double quadratic = std::abs(a) * (c.hx * c.hx) + cross + std::abs(d) * (c.hy * c.hy);
  const double ax = std::abs(a * ex) + std::abs(m * ey), ay = std::abs(m * ex) + std::abs(d * ey);
  const double S = (std::abs(ex) * ax + std::abs(ey) * ay) + 2 * (ax * c.hx + ay * c.hy) + quadratic;
  const double T = largest({a, m, d, ex, ey, c.hx, c.hy});
  if (!semi_definite(u.M)) return outward(Q - linear - quadratic, Q + linear + quadratic, S, T, -std::numeric_limits<double>::infinity());
  const Bounds r = outward(Q - linear, Q + linear + quadratic, S, T, 0);
  return {std::max(r.lo, 0.0), r.hi};
}

// d_u(p)² − d_v(p)² for every p in b lies in the bounds: the centred form of the difference,
// D(m) + 2(M_u(m − u) − M_v(m − v))ᵀδ + δᵀ(M_u − M_v)δ, whose terms in δ are far smaller than
// each distance's for two sites near each other with nearly equal metrics, seen from afar.
inline Bounds squared_distance_difference_bounds(const MetricSite& u, const MetricSite& v, const Box& b) {
  using namespace box_bounds_detail;
  const Centre c(b);
  const double ux = c.mx - u.p.x, uy = c.my - u.p.y, vx = c.mx - v.p.x, vy = c.my - v.p.y;
  const double gux = u.M.m11 * ux + u.M.m12 * uy, guy = u.M.m12 * ux + u.M.m22 * uy;
  const double gvx = v.M.m11 * vx + v.M.m12 * vy, gvy = v.M.m12 * vx + v.M.m22 * vy;
  const double D = (ux * gux + uy * guy) - (vx * gvx + vy * gvy);
  const double linear = 2 * (std::abs(gux - gvx) * c.hx + std::abs(guy - gvy) * c.hy);
  const double h11 = u.M.m11 - v.M.m11, h12 = u.M.m12 - v.M.m12, h22 = u.M.m22 - v.M.m22;
  const double sx = c.hx * c.hx, sy = c.hy * c.hy, cross = 2 * std::abs(h12) * (c.hx * c.hy);
  const double low = std::min(h11, 0.0) * sx - cross + std::min(h22, 0.0) * sy;
  const double high = std::max(h11, 0.0) * sx + cross + std::max(h22, 0.0) * sy;
  const double aux = std::abs(u.M.m11 * ux) + std::abs(u.M.m12 * uy), auy = std::abs(u.M.m12 * ux) + std::abs(u.M.m22 * uy);
  const double avx = std::abs(v.M.m11 * vx) + std::abs(v.M.m12 * vy), avy = std::abs(v.M.m12 * vx) + std::abs(v.M.m22 * vy);
  const double S = (std::abs(ux) * aux + std::abs(uy) * auy) + (std::abs(vx) * avx + std::abs(vy) * avy) +
                   2 * ((aux + avx) * c.hx + (auy + avy) * c.hy) +
                   ((std::abs(u.M.m11) + std::abs(v.M.m11)) * sx + 2 * (std::abs(u.M.m12) + std::abs(v.M.m12)) * (c.hx * c.hy) +
                    (std::abs(u.M.m22) + std::abs(v.M.m22)) * sy);
  const double T = largest({u.M.m11, u.M.m12, u.M.m22, v.M.m11, v.M.m12, v.M.m22, ux, uy, vx, vy, c.hx, c.hy});
  return outward(D - linear + low, D + linear + high, S, T, -std::numeric_limits<double>::infinity());
}

}  // namespace anisocert::refiners::common
