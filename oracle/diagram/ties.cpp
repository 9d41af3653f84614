// One-dimensional ties: a bisector that contains an edge of Ω, and three sites equidistant along
// a whole line. Both are common in degenerate inputs (symmetric sites, equal metrics) and most
// of the time harmless: the tie lies outside Ω, or another site is closer there. The oracle
// handles them exactly and declines by name only when the tie is part of D|Ω (a cell boundary
// running along ∂Ω, or three cells meeting along a curve), which the face structure does not model.
#include "oracle/algebraic/common_points.hpp"
#include "oracle/algebraic/shared_line.hpp"
#include "oracle/diagram/build.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace anisocert::oracle::build {

Nearest Builder::nearest_rational(const LocatedPoint& p) const {
  const std::vector<int> near = sites_near(p);  // they hold every nearest site
  // The site of least interval upper bound is the nearest unless another's interval overlaps it;
  // nearest() decides exactly, and when some site is closer after all, exact comparisons find it.
  int v = near[0];
  double best = std::numeric_limits<double>::infinity();
  for (int u : near) {
    const double q = distance_at(u, p).hi;
    if (q < best) best = q, v = u;
  }
  if (Nearest n = nearest(p, v); !n.closer) return n;
  for (int u : near)
    if (u != v && p.sign_of(bisector_conic(d_.sheared, u, v)) == Sign::negative) v = u;
  return nearest(p, v);
}

void Builder::decline_if_tied_on_edge(int v, int w, int edge) const {
  // Along the edge, "v and w nearest" changes only at Voronoi vertices (a third site ties) and
  // at the corners: one rational sample between consecutive ones decides.
  const auto& dom = d_.sheared.domain;
  const auto& a = dom[edge];
  const auto& b = dom[(edge + 1) % dom.size()];
  std::vector<Rational> xs{a.x, b.x};
  for (const Node& n : d_.nodes) {
    if (std::find(n.boundary_edges.begin(), n.boundary_edges.end(), edge) == n.boundary_edges.end()) continue;
    const LocatedPoint at = n.at;  // a copy: the nodes are shared by the threads building arcs
    const RealAlgebraic& x = at.exact().x();
    if (x.is_exact()) {
      xs.push_back(x.lo());
    } else {  // algebraic x: a rational just left and right of it splits the pieces too
      x.refine_below((std::max(a.x, b.x) - std::min(a.x, b.x)) / Rational(Integer(1) << 40));
      xs.push_back(x.lo()), xs.push_back(x.hi());
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    if (xs[i] < std::min(a.x, b.x) || xs[i + 1] > std::max(a.x, b.x)) continue;
    const Rational x = (xs[i] + xs[i + 1]) / 2;
    const LocatedPoint p = LocatedPoint::rational(x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x));
    const Nearest n = nearest_rational(p);
    if (std::find(n.owners.begin(), n.owners.end(), v) != n.owners.end() &&
        std::find(n.owners.begin(), n.owners.end(), w) != n.owners.end())
      throw std::domain_error("the bisector of sites " + std::to_string(v) + " and " + std::to_string(w) +
                              " runs along domain edge " + std::to_string(edge) +
                              " where both are nearest (a cell boundary along ∂Ω); such inputs are not supported yet");
  }
}

void Builder::decline_if_tied_on_line(int a, int b, int c, const Conic& G) const {
  // On G the three sites tie; "they are the nearest and the point is in Ω" changes only where G
  // meets ∂Ω or another site's bisector with a. Between consecutive such cuts one sample decides.
  std::vector<LocatedPoint> cuts;
  auto add = [&](const Conic& H) {
    CommonPoints x = exact_common_points(G, H, width_);
    if (!x.shared_component)
      for (LocatedPoint& p : x.points) cuts.push_back(std::move(p));
  };
  const auto& dom = d_.sheared.domain;
  for (std::size_t k = 0; k < dom.size(); ++k) add(line_conic(dom[k], dom[(k + 1) % dom.size()]));
  for (int s = 0; s < static_cast<int>(d_.sheared.sites.size()); ++s)
    if (s != a && s != b && s != c) add(bisector_conic(d_.sheared, a, s));
  std::sort(cuts.begin(), cuts.end(), [](const LocatedPoint& p, const LocatedPoint& q) { return compare_x(p, q) == Sign::negative; });
  const Branch line{G, 0};
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (compare_x(cuts[i], cuts[i + 1]) != Sign::negative) continue;
    const LocatedPoint p = line.at(rational_between(cuts[i], cuts[i + 1]), width_);
    if (!domain_position(p).inside) continue;
    const Nearest n = nearest(p, a, {b, c});
    if (!n.closer)
      throw std::domain_error("sites " + std::to_string(a) + ", " + std::to_string(b) + " and " + std::to_string(c) +
                              " are equidistant and nearest along a whole line inside Ω (three cells meeting along a "
                              "curve); such inputs are not supported yet");
  }
}

}  // namespace anisocert::oracle::build
