#include "refiners/star/star_set3.hpp"

#include "geometry/circumellipsoid.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::star {
namespace {

using predicates::Point3;
using predicates::Sym3;

// The search for S_v's candidates (see star_set3.hpp); margins as in 2D (star_set.cpp):
//  - a star without a reach first searches M-distance 2.5;
constexpr double default_first_reach2 = 6.25;
//  - a star fits when every circumsphere's far side is 10⁻⁴ inside the search radius;
constexpr double reach_margin = 1.0001;
//  - the search radius grows fourfold (in M-distance²).
constexpr double reach_growth = 4;

}  // namespace

StarSet3::StarSet3(const common::Domain3& domain, const common::Sites3& sites, const common::Boundary3& boundary)
    : domain_(domain), sites_(sites), boundary_(boundary), convex_(domain.convex()) {
  zones_.reset(sites_.grid);
}

void StarSet3::add(double reach2) {
  stars_.emplace_back();
  stars_.back().reach2 = reach2 > 0 ? reach2 : default_first_reach2;
}

bool StarSet3::refresh(int v, double reach2) {
  Entry& e = stars_[v];
  const auto& x = sites_.points;
  const Sym3<double>& M = sites_.metrics[v];
  e.in_domain.assign(e.star.link.size(), 1);
  e.neighbours.clear();
  common::Box3 zone;
  bool fits = true;
  const double limit = std::sqrt(reach2) / reach_margin;
  for (std::size_t i = 0; i < e.star.link.size(); ++i) {
    const auto& t = e.star.link[i];
    for (int w : t) e.neighbours.push_back(w);
    const auto c = geometry::circumellipsoid(x[v], x[t[0]], x[t[1]], x[t[2]], M);
    const Point3<double> o{x[v].x + c.x[0], x[v].y + c.x[1], x[v].z + c.x[2]};
    const common::Box3 b = std::isfinite(c.r2) ? common::metric_ball_box(o, M, c.r2) : domain_.bounding_box();
    zone = zone.hull(b);
    if (!convex_) {
      // Summed by increasing site, so that the tetrahedron's four stars round it alike.
      std::array<int, 4> s{v, t[0], t[1], t[2]};
      std::sort(s.begin(), s.end());
      const Point3<double> g{(x[s[0]].x + x[s[1]].x + x[s[2]].x + x[s[3]].x) / 4, (x[s[0]].y + x[s[1]].y + x[s[2]].y + x[s[3]].y) / 4,
                             (x[s[0]].z + x[s[1]].z + x[s[2]].z + x[s[3]].z) / 4};
      e.in_domain[i] = domain_.side(g) == common::Side::inside;
    }
    // v is on the sphere: its far side is at 2r. Only the tetrahedra in Ω must fit.
    if (e.in_domain[i] && !(2 * std::sqrt(c.r2) <= limit)) fits = false;
  }
  // An open face must lie in one of Ω's facet planes when its tetrahedron is in Ω (Ω convex: all).
  for (const auto& f : e.star.open) {
    if (boundary_.on_one_facet(v, f[0], f[1])) continue;
    bool owner_in_domain = convex_;
    for (std::size_t i = 0; i < e.star.link.size() && !owner_in_domain; ++i) {
      const auto& t = e.star.link[i];
      for (int k = 0; k < 3; ++k)
        if (t[k] == f[0] && t[(k + 1) % 3] == f[1]) owner_in_domain = e.in_domain[i];
    }
    if (owner_in_domain) fits = false;
  }
  std::sort(e.neighbours.begin(), e.neighbours.end());
  e.neighbours.erase(std::unique(e.neighbours.begin(), e.neighbours.end()), e.neighbours.end());
  zones_.set(v, zone, sites_.grid);
  return fits && !e.star.link.empty();
}

void StarSet3::recompute(int v) {
  Entry& e = stars_[v];
  const auto& x = sites_.points;
  const Sym3<double>& M = sites_.metrics[v];
  const common::Box3& box = domain_.bounding_box();
  const double dx = box.x1 - box.x0, dy = box.y1 - box.y0, dz = box.z1 - box.z0;
  // Beyond this squared M-distance from v no site lies (λ_max(M) ≤ tr M).
  const double all2 = (M.m11 + M.m22 + M.m33) * (dx * dx + dy * dy + dz * dz) * reach_margin * reach_margin;
  double reach2 = std::min(e.reach2, all2);
  for (;;) {
    cand_ = sites_.within(x[v], M, reach2);
    std::erase(cand_, v);
    e.star = gift_wrap_star3(v, cand_, x, M);
    if (refresh(v, reach2) || reach2 >= all2) break;
    reach2 = std::min(reach2 * reach_growth, all2);
  }
  e.reach2 = reach2;
}

Star3Update StarSet3::update(int v, int k) {
  Entry& e = stars_[v];
  const Star3Update u = insert_into_star3(e.star, v, k, sites_.points, sites_.metrics[v]);
  // A star updated into one that does not fit its reach (an open face off Ω's facets: v's hull
  // grew where a search may have missed sites) is wrapped again.
  if (u == Star3Update::updated && !refresh(v, e.reach2)) return Star3Update::recompute;
  return u;
}

bool StarSet3::has_tetrahedron(int v, std::array<int, 3> others) const {
  std::sort(others.begin(), others.end());
  const Entry& e = stars_[v];
  for (std::size_t i = 0; i < e.star.link.size(); ++i) {
    if (!e.in_domain[i]) continue;
    std::array<int, 3> t = e.star.link[i];
    std::sort(t.begin(), t.end());
    if (t == others) return true;
  }
  return false;
}

std::vector<std::array<int, 4>> StarSet3::consistent_tetrahedra(std::size_t& inconsistent) const {
  std::vector<std::array<int, 4>> out;
  inconsistent = 0;
  for (int v = 0; v < static_cast<int>(stars_.size()); ++v) {
    const Entry& e = stars_[v];
    for (std::size_t i = 0; i < e.star.link.size(); ++i) {
      if (!e.in_domain[i]) continue;
      const auto& t = e.star.link[i];
      const bool consistent = has_tetrahedron(t[0], {v, t[1], t[2]}) && has_tetrahedron(t[1], {v, t[0], t[2]}) &&
                              has_tetrahedron(t[2], {v, t[0], t[1]});
      if (!consistent) ++inconsistent;
      else if (v < std::min({t[0], t[1], t[2]})) out.push_back({v, t[0], t[1], t[2]});
    }
  }
  return out;
}

std::size_t StarSet3::empty_stars() const {
  std::size_t n = 0;
  for (const Entry& e : stars_) n += std::none_of(e.in_domain.begin(), e.in_domain.end(), [](char c) { return c != 0; });
  return n;
}

}  // namespace anisocert::refiners::star
