#pragma once
// Fields whose distortion is bounded everywhere (τ(p, q) ≤ γ for every two points, so bdr = ∞ in LS
// Definition 4 and BWY §4.2), and the lower bound on lfs_min that such fields give a polygon: the
// runs on which LS Theorem 11 and BWY §4.2 promise an inter-site distance that the tests can check.
#include "fields/registry.hpp"
#include "property_tests/generators/metrics.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace anisocert::gen {

// The squared M-distance from p to the segment ab (exact: the clamped projection).
inline Rational d2_to_segment(const predicates::Sym2<Rational>& M, const predicates::Point2<Rational>& p, const predicates::Point2<Rational>& a,
                       const predicates::Point2<Rational>& b) {
  const auto dot = [&](const Rational& x1, const Rational& y1, const Rational& x2, const Rational& y2) {
    return M.m11 * x1 * x2 + M.m12 * (x1 * y2 + y1 * x2) + M.m22 * y1 * y2;
  };
  const Rational ux = b.x - a.x, uy = b.y - a.y;
  const Rational t = std::clamp(dot(p.x - a.x, p.y - a.y, ux, uy) / dot(ux, uy, ux, uy), Rational(0), Rational(1));
  return d2(M, p, {a.x + t * ux, a.y + t * uy});
}

// δ², the least squared M-distance between two non-adjacent edges of the polygon q (the closest
// points of two disjoint segments include an endpoint); nothing for a triangle.
inline std::optional<Rational> nonadjacent_edges_distance2(const predicates::Sym2<Rational>& M, const std::vector<predicates::Point2<Rational>>& q) {
  const std::size_t n = q.size();
  std::optional<Rational> delta2;
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t f = e + 2; f < n; ++f) {
      if ((f + 1) % n == e) continue;  // adjacent through corner e
      const auto &a = q[e], &b = q[(e + 1) % n], &c = q[f], &d = q[(f + 1) % n];
      for (const Rational& x : {d2_to_segment(M, a, c, d), d2_to_segment(M, b, c, d), d2_to_segment(M, c, a, b), d2_to_segment(M, d, a, b)})
        if (!delta2 || x < *delta2) delta2 = x;
    }
  return delta2;
}

inline predicates::Sym2<Rational> exact(const predicates::Sym2<double>& M) { return {Rational(M.m11), Rational(M.m12), Rational(M.m22)}; }

// M with eigenvalues l1, l2 along the axes turned by angle.
inline predicates::Sym2<double> turned(double l1, double l2, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c};
}

// cos∠(u, v) <= k in M, exactly (u, v non-zero).
inline bool cos_at_most(const predicates::Sym2<Rational>& M, const Rational& ux, const Rational& uy, const Rational& vx, const Rational& vy,
                 const Rational& k) {
  const Rational uv = M.m11 * ux * vx + M.m12 * (ux * vy + uy * vx) + M.m22 * uy * vy;
  const Rational uu = M.m11 * ux * ux + 2 * M.m12 * ux * uy + M.m22 * uy * uy, vv = M.m11 * vx * vx + 2 * M.m12 * vx * vy + M.m22 * vy * vy;
  if (k >= 0) return uv <= 0 || uv * uv <= k * k * uu * vv;
  return uv < 0 && uv * uv >= k * k * uu * vv;
}

// A field of one or two metrics within τ ≤ γ of each other (Theorem 11's fields above): the
// constant field, or M_in on a disc and M_out off it, M_out with M_in's axes scaled by factors
// from 1/2 to 2 and turned by up to 20°, brought halfway to M_in (in log scale) until τ(M_in,
// M_out)² ≤ γ_lo² holds exactly. Diagonal metrics on combs, which keep their corners right.
struct TauBoundedField {
  std::vector<predicates::Sym2<double>> metrics;
  fields::MetricField field;
  std::string kind;
  double cx = 0, cy = 0, r = 0;  // the disc of metrics[0] when there are two
};

inline TauBoundedField tau_bounded_field(const std::vector<predicates::Point2<double>>& corners, bool diagonal, const Rational& gamma_lo2) {
  const double l1 = *rc::gen::inRange(1, 101), l2 = *rc::gen::inRange(1, 101);
  const double angle = diagonal ? 0 : *rc::gen::inRange(0, 180) * M_PI / 180;
  const predicates::Sym2<double> in = turned(l1, l2, angle);
  if (*rc::gen::arbitrary<bool>())
    return {{in}, fields::make_field("constant", {{"m11", in.m11}, {"m12", in.m12}, {"m22", in.m22}}), "one metric"};
  double a = *rc::gen::inRange(50, 201) / 100.0, b = *rc::gen::inRange(50, 201) / 100.0;
  double turn = diagonal ? 0 : *rc::gen::inRange(-20, 21) * M_PI / 180;
  predicates::Sym2<double> out = turned(l1 * a, l2 * b, angle + turn);
  while (tau2_above(exact(in), exact(out)) > gamma_lo2) {
    a = std::sqrt(a), b = std::sqrt(b), turn /= 2;
    out = turned(l1 * a, l2 * b, angle + turn);
  }
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& c : corners) x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  const double cx = x0 + (x1 - x0) * *rc::gen::inRange(0, 101) / 100, cy = y0 + (y1 - y0) * *rc::gen::inRange(0, 101) / 100;
  const double r = std::max(x1 - x0, y1 - y0) * *rc::gen::inRange(10, 71) / 100;
  fields::MetricField field{"two metrics", {}, [=](double x, double y) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r ? in : out; }};
  RC_LOG() << std::hexfloat << "M_in " << in.m11 << " " << in.m12 << " " << in.m22 << ", M_out " << out.m11 << " " << out.m12 << " " << out.m22
           << " off the disc (x - " << cx << ")² + (y - " << cy << ")² <= " << r << "²" << std::defaultfloat << "\n";
  return {{in, out}, field, "two metrics", cx, cy, r};
}

}  // namespace anisocert::gen
