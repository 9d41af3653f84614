#include "refiners/star/pick_valid3.hpp"

#include "geometry/circumellipsoid.hpp"
#include "predicates/distortion.hpp"
#include "predicates/quasi_cospherical.hpp"
#include "refiners/star/gift_wrap3.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace anisocert::refiners::star {

using predicates::Point3;
using predicates::Sym3;

bool PickValid3::forbidden(const Point3<double>& x, double r_tau) {
  if (cand_.size() < 4 || domain_.side(x) != common::Side::inside) return false;
  const Sym3<double> M = sites_.field.at(x.x, x.y, x.z);
  // x's star in M_x among the candidates: x is the last of the local points.
  local_.clear();
  for (int s : cand_) local_.push_back(sites_.points[s]);
  local_.push_back(x);
  const int xi = static_cast<int>(cand_.size());
  local_index_.resize(cand_.size());
  std::iota(local_index_.begin(), local_index_.end(), 0);
  const Star3 star = gift_wrap_star3(xi, local_index_, local_, M);
  const double g2 = p_.gamma0 * p_.gamma0, g4 = g2 * g2, k = g4 - 1, beta_r2 = p_.beta * p_.beta * r_tau * r_tau,
               rho2 = p_.rho0 * p_.rho0;
  const auto d2 = [&](const Point3<double>& a, const Point3<double>& b) { return predicates::quadratic_form(M, a.x - b.x, a.y - b.y, a.z - b.z); };
  const auto& m = sites_.metrics;
  for (const auto& t : star.link) {
    const std::array<int, 3> s{cand_[t[0]], cand_[t[1]], cand_[t[2]]};
    bool within = true;  // γ(xpqr) < γ₀: the metrics pairwise within γ₀ (M_x for x)
    for (int a = 0; a < 3 && within; ++a) {
      within = predicates::tau_at_most(M, m[s[a]], g2);
      for (int b = a + 1; b < 3 && within; ++b) within = predicates::tau_at_most(m[s[a]], m[s[b]], g2);
    }
    if (!within) continue;
    const Point3<double>&p = local_[t[0]], &q = local_[t[1]], &r = local_[t[2]];
    const auto c = geometry::circumellipsoid(x, p, q, r, M);
    if (!(c.r2 < beta_r2)) continue;
    const Point3<double> o{x.x + c.x[0], x.y + c.x[1], x.z + c.x[2]};
    const double edges = std::min({d2(x, p), d2(x, q), d2(x, r), d2(p, q), d2(p, r), d2(q, r)});
    for (int e = 0; e < xi; ++e) {
      if (e == t[0] || e == t[1] || e == t[2]) continue;
      const Point3<double>& w = local_[e];
      const double from_centre = d2(w, o);
      if (from_centre * g4 < c.r2 || from_centre > c.r2 * g4) continue;
      if (!(c.r2 < rho2 * std::min({edges, d2(w, x), d2(w, p), d2(w, q), d2(w, r)}))) continue;
      if (predicates::quasi_cospherical(x, p, q, r, w, M, k) == Sign::positive) return true;  // strictly γ₀-cospherical
    }
  }
  return false;
}

Point3<double> PickValid3::pick(const Point3<double>& o, double r2, const Sym3<double>& M, const std::array<int, 4>& q) {
  const auto& pts = sites_.points;
  // M = LLᵀ (Cholesky); a point of the M-ball: o + L⁻ᵀ (δ r u) with |u| < 1.
  const double l11 = std::sqrt(M.m11), l21 = M.m12 / l11, l31 = M.m13 / l11, l22 = std::sqrt(M.m22 - l21 * l21),
               l32 = (M.m23 - l31 * l21) / l22, l33 = std::sqrt(M.m33 - l31 * l31 - l32 * l32);
  std::uniform_real_distribution<double> unit(-1, 1);
  const double s = p_.delta * std::sqrt(r2);
  if (p_.pick_attempts > 0) cand_ = sites_.within(o, M, std::pow(2 + p_.delta, 2) * r2);
  Point3<double> x;
  for (int attempt = 0;; ++attempt) {
    double ux, uy, uz;
    do ux = unit(rng_), uy = unit(rng_), uz = unit(rng_);
    while (ux * ux + uy * uy + uz * uz >= 1);
    // Lᵀ z = s u, back substitution.
    const double zz = s * uz / l33, zy = (s * uy - l32 * zz) / l22, zx = (s * ux - l21 * zy - l31 * zz) / l11;
    x = {o.x + zx, o.y + zy, o.z + zz};
    const bool finite = std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z);
    if (p_.pick_attempts == 0 || !finite || !forbidden(x, std::sqrt(r2))) break;
    if (attempt == p_.pick_attempts) {
      ++counts_.exhausted;
      break;
    }
    ++counts_.rejected;
  }
  if (!(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z))) {
    x = {0, 0, 0};
    for (int w : q) x = {x.x + pts[w].x / 4, x.y + pts[w].y / 4, x.z + pts[w].z / 4};
  }
  return x;
}

}  // namespace anisocert::refiners::star
