#include "refiners/star/pick_valid.hpp"

#include "geometry/distortion_estimate.hpp"
#include "geometry/ellipse_box.hpp"
#include "refiners/star/gift_wrap.hpp"
#include "refiners/star/quasi_cocircular.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::star {

using predicates::Point2;
using predicates::Sym2;

// A point x is discarded while it would make a new triangle xpq with γ(xpq) < γ₀ that is
// γ₀-cocircular with a site s, with radius < β r_τ and radius-edge ratio < ρ₀ (both measured on xpq,
// which bounds LU Definition 3.9's minimum over the four triples from above: every configuration
// found here is one LU forbids). The new triangles are x's prospective fan in M_x, wrapped
// counter-clockwise from x's nearest site and tested as they are found, so a forbidden point costs
// only the triangles before the first hit.
bool PickValid::forbidden(const Point2<double>& x, double r_tau, const std::vector<int>& cand) const {
  if (cand.size() < 3 || !domain_.contains(x)) return false;
  const auto& pts = sites_.points;
  const Sym2<double> M = sites_.field.at(x.x, x.y);
  auto d2 = [&](const Point2<double>& p, const Point2<double>& q) { return predicates::quadratic_form(M, p.x - q.x, p.y - q.y); };
  const int first = nearest_candidate(x, M, cand, pts);
  const double g2 = p_.gamma0 * p_.gamma0, beta_r2 = p_.beta * p_.beta * r_tau * r_tau, rho2 = p_.rho0 * p_.rho0;
  int a = first;
  for (std::size_t guard = 0; guard <= cand.size(); ++guard) {
    const int b = next_delaunay_neighbour(x, M, a, cand, true, pts);
    if (b < 0) return false;
    const Point2<double>&pa = pts[a], &pb = pts[b];
    if (geometry::pairwise_tau_squared_below(M, sites_.metrics[a], sites_.metrics[b], g2)) {
      const geometry::Circumellipse<double> c = geometry::circumellipse(x, pa, pb, M);
      const double edges = std::min({d2(pa, x), d2(pb, x), d2(pa, pb)});
      if (c.r2 < beta_r2)
        for (int sx : cand) {
          if (sx == a || sx == b) continue;
          const Point2<double>& ps = pts[sx];
          if (c.r2 < rho2 * std::min({edges, d2(ps, x), d2(ps, pa), d2(ps, pb)}) && quasi_cocircular(x, pa, pb, ps, M, p_.gamma0))
            return true;
        }
    }
    if (b == first) return false;
    a = b;
  }
  return false;
}

Point2<double> PickValid::pick(const geometry::Circumellipse<double>& c, const Sym2<double>& M, int v, int a, int b) {
  const auto& pts = sites_.points;
  // M = LLᵀ; a point of the M-ball: c + L⁻ᵀ (δ r u) with |u| < 1.
  const double l11 = std::sqrt(M.m11), l21 = M.m12 / l11, l22 = std::sqrt(M.m22 - l21 * l21);
  std::uniform_real_distribution<double> unit(-1, 1);
  const double s = p_.delta * std::sqrt(c.r2);
  if (p_.pick_attempts > 0) {
    // The sites within M-distance (2 + δ) r of the centre: x's new fan lies among them.
    const double reach2 = std::pow(2 + p_.delta, 2) * c.r2;
    const auto e = geometry::ellipse_half_widths(M, reach2);
    cand_ = sites_.in({c.cx - e.hx, c.cx + e.hx, c.cy - e.hy, c.cy + e.hy});
    std::erase_if(cand_, [&](int w) { return predicates::quadratic_form(M, pts[w].x - c.cx, pts[w].y - c.cy) > reach2; });
  }
  Point2<double> x;
  for (int attempt = 0;; ++attempt) {
    double ux, uy;
    do ux = unit(rng_), uy = unit(rng_);
    while (ux * ux + uy * uy >= 1);
    const double zy = s * uy / l22, zx = (s * ux - l21 * zy) / l11;
    x = {c.cx + zx, c.cy + zy};
    if (p_.pick_attempts == 0 || !std::isfinite(x.x) || !std::isfinite(x.y) || !forbidden(x, std::sqrt(c.r2), cand_)) break;
    if (attempt == p_.pick_attempts) {
      ++counts_.exhausted;
      break;
    }
    ++counts_.rejected;
  }
  if (!std::isfinite(x.x) || !std::isfinite(x.y))  // a nearly flat triangle
    x = {(pts[v].x + pts[a].x + pts[b].x) / 3, (pts[v].y + pts[a].y + pts[b].y) / 3};
  return x;
}

}  // namespace anisocert::refiners::star
