#pragma once
// The bisector conic of two sites v, w (LS Proposition 2): B = Q_v − Q_w = 0 with
//   B(x, y) = a x² + b xy + c y² + d x + e y + f,
// negative on v's side. A curve made of pieces that are graphs over x, joined at vertical tangents
// (the way CGAL's Arr_conic_traits_2 and the oracle's branches cut conics): a point P of the curve
// lies on the piece named by σ = sign ∂B/∂y(P) (and, for a hyperbola with two x-ranges, by the side
// of x* where Δ is least), and along a piece points are ordered by x. Moving along the curve with v
// on the left, i.e. along rot90 ∇B = (−B_y, B_x), a piece is run in the x-direction −σ.
//
// With Δ(x) = L x² + K x + C the discriminant of B in y (L = b² − 4ac, K = 2be − 4cd, C = e² − 4cf):
//   ellipse (L < 0): two pieces, a cycle;
//   hyperbola (L > 0, c ≠ 0) with Δ(x*) < 0, x* = −K/(2L): two x-ranges, each with two pieces joined
//     at the inner vertical tangent and running to infinity outward;
//   hyperbola with Δ(x*) > 0: each piece a whole branch, to infinity both ways;
//   hyperbola with c = 0: the pieces either side of the vertical asymptote x = −e/b;
//   parabola (L = 0, c ≠ 0): two pieces joined at the vertical tangent, which lies towards −sign K;
//   parabola with c = 0 (b = 0): one piece, a graph y(x);
//   line (a = b = c = 0, equal metrics): one piece, ordered along its direction (−e, d).
// Degenerate conics (a line pair, a point, two coincident sites) are refused by the constructor's
// `shape()` = degenerate: callers stop by name (issue 16's plan, C5). Every shape is decided exactly.

#include "refiners/common/certified_point.hpp"

#include <span>

namespace anisocert::refiners::common {

template <class T>
struct ConicIn {
  T a, b, c, d, e, f;
};

// B's coefficients from the two sites in T: Q_s = xᵀM x − 2 xᵀ M s + sᵀ M s.
template <class T>
ConicIn<T> bisector_coefficients(const SiteIn<T>& v, const SiteIn<T>& w) {
  const auto q = [](const SiteIn<T>& s) {
    const T gx = s.m11 * s.x + s.m12 * s.y, gy = s.m12 * s.x + s.m22 * s.y;  // M s
    return ConicIn<T>{s.m11, s.m12 + s.m12, s.m22, -(gx + gx), -(gy + gy), s.x * gx + s.y * gy};
  };
  const ConicIn<T> p = q(v), r = q(w);
  return {p.a - r.a, p.b - r.b, p.c - r.c, p.d - r.d, p.e - r.e, p.f - r.f};
}

class BisectorConic {
 public:
  enum class Shape {
    line,
    ellipse,
    hyperbola_two_ranges,    // Δ(x*) < 0
    hyperbola_two_branches,  // Δ(x*) > 0
    hyperbola_vertical_asymptote,
    parabola,
    parabola_graph,  // c = 0
    degenerate,
  };
  // Which piece of the curve a point is on: σ = sign B_y, and the side of x* (±1) for
  // hyperbola_two_ranges, else 0.
  struct Piece {
    int sigma = 0, side = 0;
    friend bool operator==(const Piece&, const Piece&) = default;
  };

  BisectorConic(const MetricSite& v, const MetricSite& w);
  Shape shape() const { return shape_; }
  const MetricSite& left() const { return v_; }
  const MetricSite& right() const { return w_; }

  // P's piece (P on the curve); nothing when undecided (P at a vertical tangent, or too close).
  std::optional<Piece> piece(const CertifiedPoint& p) const;

  // The index of the first of `candidates` (points of the curve, distinct from p and from each
  // other) reached from p moving along the curve with v on the left; −1 when the curve runs to
  // infinity first; nothing when a decision is undecided.
  std::optional<int> first_after(const CertifiedPoint& p, std::span<const CertifiedPoint* const> candidates) const;

 private:
  // Whether the piece's end in its direction of travel (−σ) is a vertical tangent.
  bool turns(const Piece& p) const;

  MetricSite v_, w_;
  Shape shape_ = Shape::degenerate;
  int k_sign_ = 0;  // sign K, for parabolas
};

}  // namespace anisocert::refiners::common
