#include "refiners/star/rules3.hpp"

#include "geometry/circumellipsoid.hpp"
#include "predicates/distortion.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::star {
namespace {

using predicates::Point3;
using predicates::Sym3;

// As in 2D (rules.cpp): rules 2 and 3 fire a hair early (relative 10⁻⁹), so that a consistent
// mesh also passes the certifier's exact checks at exactly γ₀ and ρ₀.
constexpr double fire_early = 1 - 1e-9;

}  // namespace

Action3 first_rule3(int v, const StarSet3& stars, const common::Sites3& sites, const common::Domain3& domain, const RefineParameters& p) {
  const Star3& s = stars.star(v);
  const Sym3<double>& M = sites.metrics[v];
  const auto& x = sites.points;
  const auto& m = sites.metrics;
  const double g2 = p.gamma0 * p.gamma0 * fire_early, rho2 = p.rho0 * p.rho0 * fire_early, size2 = p.size * p.size;
  Action3 best;
  const auto consider = [&](Rule rule, const std::array<int, 3>& t) {
    if (best.rule == Rule::none || rule < best.rule) best = {rule, t};
  };
  for (std::size_t i = 0; i < s.link.size(); ++i) {
    if (!stars.in_domain(v, i)) continue;
    const auto& t = s.link[i];
    const std::array<int, 4> q{v, t[0], t[1], t[2]};
    const auto c = geometry::circumellipsoid(x[v], x[t[0]], x[t[1]], x[t[2]], M);
    bool distorted = false;
    for (int a = 0; a < 4 && !distorted; ++a)
      for (int b = a + 1; b < 4 && !distorted; ++b) distorted = !predicates::tau_at_most(m[q[a]], m[q[b]], g2);
    const Point3<double> o{x[v].x + c.x[0], x[v].y + c.x[1], x[v].z + c.x[2]};
    if (!distorted && std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) && domain.side(o) == common::Side::inside) {
      const Sym3<double> Mo = sites.field.at(o.x, o.y, o.z);
      for (int w : q) distorted = distorted || !predicates::tau_at_most(Mo, m[w], g2);
    }
    if (distorted) consider(Rule::distortion, t);
    double shortest = INFINITY;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        shortest = std::min(shortest, predicates::quadratic_form(M, x[q[b]].x - x[q[a]].x, x[q[b]].y - x[q[a]].y, x[q[b]].z - x[q[a]].z));
    if (c.r2 > rho2 * shortest) consider(Rule::radius_edge, t);
    if (c.r2 > size2) consider(Rule::size, t);
  }
  if (best.rule != Rule::none) return best;
  double largest = -1;
  for (std::size_t i = 0; i < s.link.size(); ++i) {
    if (!stars.in_domain(v, i)) continue;
    const auto& t = s.link[i];
    if (!stars.has_tetrahedron(t[0], {v, t[1], t[2]}) || !stars.has_tetrahedron(t[1], {v, t[0], t[2]}) ||
        !stars.has_tetrahedron(t[2], {v, t[0], t[1]})) {
      const double r2 = geometry::circumellipsoid(x[v], x[t[0]], x[t[1]], x[t[2]], M).r2;
      if (r2 > largest) largest = r2, best = {Rule::inconsistency, t};
    }
  }
  return best;
}

}  // namespace anisocert::refiners::star
