#include "refiners/star/gift_wrap.hpp"

#include "predicates/incircle.hpp"
#include "predicates/orientation.hpp"

namespace anisocert::refiners::star {

int next_delaunay_neighbour(const predicates::Point2<double>& pv, const predicates::Sym2<double>& M, int u,
                            const std::vector<int>& cand, bool ccw, const std::vector<predicates::Point2<double>>& points) {
  const predicates::Point2<double>& pu = points[u];
  int w = -1;
  for (int x : cand) {
    if (x == u) continue;
    const Sign side = predicates::orientation(pv, pu, points[x]);
    if (side != (ccw ? Sign::positive : Sign::negative)) continue;
    if (w < 0) {
      w = x;
      continue;
    }
    // Triangle (p, u, w) counter-clockwise for ccw, (p, w, u) for cw: is x inside its circle?
    const Sign in = ccw ? predicates::incircle(pv, pu, points[w], points[x], M) : predicates::incircle(pv, points[w], pu, points[x], M);
    const bool closer_in_angle = predicates::orientation(pv, points[w], points[x]) == (ccw ? Sign::negative : Sign::positive);
    if (in == Sign::positive || (in == Sign::zero && closer_in_angle)) w = x;
  }
  return w;
}

}  // namespace anisocert::refiners::star
