#include "refiners/star/gift_wrap.hpp"

#include "predicates/incircle.hpp"
#include "predicates/length_compare.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::refiners::star {

int nearest_candidate(const predicates::Point2<double>& p, const predicates::Sym2<double>& M, const std::vector<int>& cand,
                      const std::vector<predicates::Point2<double>>& points) {
  // d = dᵀMd in doubles is within 16u·A of the exact value, A = |m11|dx² + 2|m12||dx dy| + |m22|dy²
  // (the differences rounded once, then six operations; u = 2⁻⁵³), unless A is so small that
  // underflow voids the relative bound, or not finite: then every candidate is kept.
  constexpr double bound = 16 * 0x1p-53, tiny = 0x1p-900;
  std::vector<double> lo(cand.size()), hi(cand.size());
  double least_hi = std::numeric_limits<double>::infinity();
  bool all = false;
  for (std::size_t i = 0; i < cand.size(); ++i) {
    const double dx = points[cand[i]].x - p.x, dy = points[cand[i]].y - p.y;
    const double d = predicates::quadratic_form(M, dx, dy);
    const double a = std::abs(M.m11) * dx * dx + 2 * std::abs(M.m12) * std::abs(dx * dy) + std::abs(M.m22) * dy * dy;
    if (!std::isfinite(a) || (a < tiny && a != 0)) all = true;
    lo[i] = d - bound * a, hi[i] = d + bound * a;
    least_hi = std::min(least_hi, hi[i]);
  }
  int best = -1;
  for (std::size_t i = 0; i < cand.size(); ++i)
    if ((all || lo[i] <= least_hi) &&
        (best < 0 || predicates::compare_scaled_lengths(1.0, p, points[cand[i]], M, p, points[best], M) == Sign::negative))
      best = cand[i];
  return best;
}

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
