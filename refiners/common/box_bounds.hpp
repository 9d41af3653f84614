#pragma once
// Bounds over a box of a site's squared distance d_u(p)² = (p − u)ᵀM_u(p − u), and of the
// difference of two sites', for the subdivision's candidates (vertex_subdivision.hpp): its hot path,
// so computed in doubles with one rounding bound at the end instead of an interval per operation.
//
// Centred form about the box's midpoint m, p = m + δ, |δ_x| ≤ h_x, |δ_y| ≤ h_y:
//   d_u(m + δ)² = Q + 2gᵀδ + δᵀMδ,  g = M(m − u),  Q = (m − u)ᵀg,
// so Q − 2(|g_x|h_x + |g_y|h_y) ≤ d² ≤ Q + 2(|g_x|h_x + |g_y|h_y) + M₁₁h_x² + 2|M₁₂|h_xh_y + M₂₂h_y²,
// and δᵀMδ ≥ 0 when M is positive semi-definite (checked with a margin; else −2|M₁₂|h_xh_y).
//
// Rounding (N. Higham, Accuracy and Stability of Numerical Algorithms, §3.1): every quantity is a
// sum of products computed in at most 8 operations, each within a relative ε = 2⁻⁵³ when nothing
// underflows, so its error is at most γ₈ = 8ε/(1 − 8ε) < 2⁻⁴⁹ times S, the same sum with every
// term replaced by its absolute value (S itself computed within the same relative error). Each end
// is moved outward by 2⁻⁴⁵·S (16 times that), plus 2⁻¹⁰⁰⁰ for underflow (each of the few dozen
// operations loses at most 2⁻¹⁰⁷⁵ to it). An infinite or NaN value gives [0, ∞] (no bound).
// `BoxBounds.HoldEveryExactValueInTheBox` checks both bounds against rationals.
#include "refiners/common/domain.hpp"
#include "refiners/common/distance_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::refiners::common {

struct Bounds {
  double lo, hi;
};

namespace box_bounds_detail {

struct Centre {
  double mx, my, hx, hy;  // the midpoint, and half-widths from above
  explicit Centre(const Box& b)
      : mx(b.x0 / 2 + b.x1 / 2), my(b.y0 / 2 + b.y1 / 2), hx(std::max(b.x1 - mx, mx - b.x0)), hy(std::max(b.y1 - my, my - b.y0)) {}
};

inline Bounds outward(double lo, double hi, double S) {
  const double e = 0x1p-45 * S + 0x1p-1000;
  lo -= e, hi += e;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0, std::numeric_limits<double>::infinity()};
  return {lo, hi};
}

// δᵀMδ's least value over the box, when M is certainly positive semi-definite: 0.
inline bool semi_definite(const Sym2<double>& M) { return M.m11 >= 0 && M.m22 >= 0 && M.m12 * M.m12 <= (M.m11 * M.m22) * (1 - 0x1p-48); }

}  // namespace box_bounds_detail

// d_u(p)² for every p in b lies in the bounds (the lower one is at least 0).
inline Bounds squared_distance_bounds(const MetricSite& u, const Box& b) {
  const box_bounds_detail::Centre c(b);
  const double ex = c.mx - u.p.x, ey = c.my - u.p.y;
  const double a = u.M.m11, m = u.M.m12, d = u.M.m22;
  const double gx = a * ex + m * ey, gy = m * ex + d * ey;
  const double Q = ex * gx + ey * gy;
  const double linear = 2 * (std::abs(gx) * c.hx + std::abs(gy) * c.hy);
  const double cross = 2 * std::abs(m) * (c.hx * c.hy);
  const double quadratic = std::abs(a) * (c.hx * c.hx) + cross + std::abs(d) * (c.hy * c.hy);
  const double ax = std::abs(a * ex) + std::abs(m * ey), ay = std::abs(m * ex) + std::abs(d * ey);
  const double S = (std::abs(ex) * ax + std::abs(ey) * ay) + 2 * (ax * c.hx + ay * c.hy) + quadratic;
  const double least_quadratic = box_bounds_detail::semi_definite(u.M) ? 0.0 : -cross;
  const Bounds r = box_bounds_detail::outward(Q - linear + least_quadratic, Q + linear + quadratic, S);
  return {std::max(r.lo, 0.0), r.hi};
}

// d_u(p)² − d_v(p)² for every p in b lies in the bounds: the centred form of the difference,
// D(m) + 2(M_u(m − u) − M_v(m − v))ᵀδ + δᵀ(M_u − M_v)δ, whose terms in δ are far smaller than
// each distance's for two sites near each other with nearly equal metrics, seen from afar.
inline Bounds squared_distance_difference_bounds(const MetricSite& u, const MetricSite& v, const Box& b) {
  const box_bounds_detail::Centre c(b);
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
  return box_bounds_detail::outward(D - linear + low, D + linear + high, S);
}

}  // namespace anisocert::refiners::common
