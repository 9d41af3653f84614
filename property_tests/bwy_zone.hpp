#pragma once
// BWY Lemma 2's zone Z = B(a, r) ∩ B(b, r) ∩ B(c, r) ∩ B(d, r) (B(x, r) = {y : d_x(x, y) ≤ r}),
// from inside: rational convex polygons inscribed in the balls and their intersection, for the
// exact diagram of {a, b, c, d} restricted to a polygon P ⊆ Z (property tests of BWY_L2).
#include "numbers/rational.hpp"
#include "predicates/point.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

namespace anisocert::gen {

using predicates::Point2;

// A rational just above √x (x ≥ 0 rational), and one just below.
inline Rational sqrt_above(const Rational& x) {
  Rational r(static_cast<long>(std::ceil(std::sqrt(x.convert_to<double>()) * 1e9)) + 1, 1000000000);
  while (r * r < x) r += Rational(1, 1000000000);
  return r;
}
inline Rational sqrt_below(const Rational& x) {
  Rational r(static_cast<long>(std::floor(std::sqrt(x.convert_to<double>()) * 1e6)), 1000000);
  while (r > 0 && r * r > x) r -= Rational(1, 1000000);
  return r;
}

// Sutherland–Hodgman, exact: the part of the convex counter-clockwise polygon p left of or on
// every edge of the convex counter-clockwise polygon c.
inline std::vector<Point2<Rational>> clip(std::vector<Point2<Rational>> p, const std::vector<Point2<Rational>>& c) {
  for (std::size_t k = 0; k < c.size() && !p.empty(); ++k) {
    const auto& a = c[k];
    const auto& b = c[(k + 1) % c.size()];
    auto side = [&](const Point2<Rational>& q) { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
    std::vector<Point2<Rational>> out;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto& s = p[i];
      const auto& e = p[(i + 1) % p.size()];
      const Rational ss = side(s), se = side(e);
      if (ss >= 0) out.push_back(s);
      if ((ss > 0 && se < 0) || (ss < 0 && se > 0)) {
        const Rational t = ss / (ss - se);
        out.push_back({s.x + t * (e.x - s.x), s.y + t * (e.y - s.y)});
      }
    }
    std::vector<Point2<Rational>> dedup;
    for (const auto& q : out)
      if (dedup.empty() || q.x != dedup.back().x || q.y != dedup.back().y) dedup.push_back(q);
    while (dedup.size() > 1 && dedup.front().x == dedup.back().x && dedup.front().y == dedup.back().y) dedup.pop_back();
    p = dedup;
  }
  return p;
}

// Twenty rational unit vectors in counter-clockwise order.
inline std::vector<Point2<Rational>> directions() {
  std::vector<Point2<Rational>> u;
  const std::vector<std::pair<Rational, Rational>> first{{1, 0}, {Rational(12, 13), Rational(5, 13)}, {Rational(4, 5), Rational(3, 5)},
                                                         {Rational(3, 5), Rational(4, 5)}, {Rational(5, 13), Rational(12, 13)}};
  for (int q = 0; q < 4; ++q)
    for (std::size_t i = 0; i < first.size(); ++i) {
      auto [x, y] = first[i];
      for (int r = 0; r < q; ++r) std::tie(x, y) = std::pair{-y, x};  // rotate by 90°
      u.push_back({x, y});
    }
  return u;
}

// A convex polygon inside the ball {y : (y − p)ᵀM(y − p) ≤ r2} (convex, so the hull of points in it
// is): p + t_u u for each of directions()' u, t_u a rational with t_u² uᵀMu ≤ r2.
inline std::vector<Point2<Rational>> inscribed_ball(const Point2<Rational>& p, const predicates::Sym2<Rational>& M, const Rational& r2) {
  std::vector<Point2<Rational>> out;
  for (const auto& u : directions()) {
    const Rational t = sqrt_below(r2 / (M.m11 * u.x * u.x + 2 * M.m12 * u.x * u.y + M.m22 * u.y * u.y));
    out.push_back({p.x + t * u.x, p.y + t * u.y});
  }
  return out;
}

}  // namespace anisocert::gen
