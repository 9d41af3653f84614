#include "refiners/star/rules.hpp"

#include "geometry/circumellipse.hpp"
#include "geometry/distortion_estimate.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::star {

using predicates::Sym2;

const char* rule_name(Rule rule) {
  switch (rule) {
    case Rule::none: return "none";
    case Rule::encroachment: return "encroachment";
    case Rule::distortion: return "distortion";
    case Rule::radius_edge: return "radius-edge ratio";
    case Rule::size: return "size";
    case Rule::inconsistency: return "inconsistency";
  }
  return "none";
}

namespace {

// Rules 2 and 3 fire a hair early (relative 10⁻⁹, far above the rounding of the doubles they are
// computed in), so that a consistent mesh also passes the certifier's exact checks at exactly γ₀
// and ρ₀. A floating-point choice of where to refine: it cannot make a star wrong.
constexpr double fire_early = 1 - 1e-9;

// LU's total distortion γ(τ) is the largest distortion between two points of Ω in one of τ's
// circumballs; it is estimated from below on samples of the star's own circumball: the three
// vertices and, when it lies in Ω, the circumcentre (the other vertices' stars sample theirs).
bool distorted(const Sym2<double>& Mv, const Sym2<double>& Ma, const Sym2<double>& Mb,
               const geometry::Circumellipse<double>& c, double g2, const common::Domain& domain,
               const fields::MetricField& field) {
  if (!geometry::pairwise_tau_squared_below(Mv, Ma, Mb, g2)) return true;
  if (!std::isfinite(c.cx) || !std::isfinite(c.cy) || !domain.contains(predicates::Point2<double>{c.cx, c.cy})) return false;
  const Sym2<double> Mc = field.at(c.cx, c.cy);
  return geometry::tau_squared_estimate(Mc, Mv) >= g2 || geometry::tau_squared_estimate(Mc, Ma) >= g2 ||
         geometry::tau_squared_estimate(Mc, Mb) >= g2;
}

}  // namespace

Action first_rule(int v, const StarSet& stars, const common::Sites& sites, const common::Domain& domain,
                  const RefineParameters& p) {
  const Star& s = stars[v];
  const Sym2<double>& M = sites.metrics[v];
  const auto& x = sites.points;
  const double g2 = p.gamma0 * p.gamma0 * fire_early, rho2 = p.rho0 * p.rho0 * fire_early, size2 = p.size * p.size;
  Action best;
  auto consider = [&](Rule rule, int a, int b) {
    if (best.rule == Rule::none || rule < best.rule) best = {rule, a, b};
  };
  for (const auto& t : s.triangles) {
    const int a = t[0], b = t[1];
    const geometry::Circumellipse<double> c = geometry::circumellipse(x[v], x[a], x[b], M);
    if (distorted(M, sites.metrics[a], sites.metrics[b], c, g2, domain, sites.field)) consider(Rule::distortion, a, b);
    const double shortest = std::min({predicates::quadratic_form(M, x[a].x - x[v].x, x[a].y - x[v].y),
                                      predicates::quadratic_form(M, x[b].x - x[v].x, x[b].y - x[v].y),
                                      predicates::quadratic_form(M, x[b].x - x[a].x, x[b].y - x[a].y)});
    if (c.r2 > rho2 * shortest) consider(Rule::radius_edge, a, b);
    if (c.r2 > size2) consider(Rule::size, a, b);
  }
  if (best.rule != Rule::none) return best;
  // LU Definition 3.3 at the level of triangles: (v, a, b) must also be (a, b, v) in S_a and
  // (b, v, a) in S_b (edge-consistency alone lets two fans disagree on the third vertex).
  for (const auto& t : s.triangles)
    if (!stars.has_triangle(t[0], t[1], v) || !stars.has_triangle(t[1], v, t[0])) return {Rule::inconsistency, t[0], t[1]};
  return best;
}

}  // namespace anisocert::refiners::star
