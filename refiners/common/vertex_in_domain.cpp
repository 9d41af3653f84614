#include "refiners/common/vertex_in_domain.hpp"

#include <algorithm>

namespace anisocert::refiners::common {

std::optional<bool> in_closed_domain(const Domain& domain, const CertifiedPoint& p) {
  const auto& b = p.box();
  if (const auto in = domain.contains(Box{b.x.lo, b.x.hi, b.y.lo, b.y.hi})) return *in;
  const auto& corners = domain.corners();
  const auto above = [&](double y) {  // sign(y − p.y)
    return sign_at<1>({&p}, [y](const auto& P, auto of) { return of(y) - P[0].y; });
  };
  const auto side = [&](const Point2<double>& u, const Point2<double>& v) {  // orientation(u, v, p)
    return sign_at<1>({&p}, [&](const auto& P, auto of) { return (of(v.x) - of(u.x)) * (P[0].y - of(u.y)) - (of(v.y) - of(u.y)) * (P[0].x - of(u.x)); });
  };
  // The crossings of a ray from p to the right (or to the left): edges that cannot meet the ray
  // from any point of p's box, nor hold p, are skipped undecided (a vertex at a corner's height
  // beyond the ray's side, or on the line of an edge there).
  const auto crossings = [&](bool right) -> std::optional<bool> {
    bool inside = false;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Point2<double>&u = corners[i], &v = corners[(i + 1) % corners.size()];
      if (std::max(u.y, v.y) < b.y.lo || std::min(u.y, v.y) > b.y.hi) continue;
      if (right ? std::max(u.x, v.x) < b.x.lo : std::min(u.x, v.x) > b.x.hi) continue;
      const auto su = above(u.y), sv = above(v.y), o = side(u, v);
      if (!su || !sv || !o) return std::nullopt;
      if (*o == Sign::zero) {  // on the edge's line: on the edge when within its extent
        const auto between = [&](double lo, double hi, bool x) {
          const auto s1 = sign_at<1>({&p}, [&](const auto& P, auto of) { return (x ? P[0].x : P[0].y) - of(lo); });
          const auto s2 = sign_at<1>({&p}, [&](const auto& P, auto of) { return of(hi) - (x ? P[0].x : P[0].y); });
          return s1 && s2 && *s1 != Sign::negative && *s2 != Sign::negative;
        };
        if (between(std::min(u.x, v.x), std::max(u.x, v.x), true) && between(std::min(u.y, v.y), std::max(u.y, v.y), false)) return true;
      }
      // Half-open in y: an edge counts when p's height is in [min, max) of its ends' heights; it
      // crosses the ray to the right when p is left of the upward edge (right of the downward),
      // and the ray to the left when p is right of it (left of the downward).
      const bool u_above = *su == Sign::positive, v_above = *sv == Sign::positive;
      if (u_above == v_above) continue;
      const Sign ahead = v_above == right ? Sign::positive : Sign::negative;
      if (*o == ahead) inside = !inside;
    }
    return inside;
  };
  if (const auto in = crossings(true)) return in;
  return crossings(false);
}

}  // namespace anisocert::refiners::common
