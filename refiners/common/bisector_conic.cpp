#include "refiners/common/bisector_conic.hpp"

#include <vector>

namespace anisocert::refiners::common {
namespace {

using Shape = BisectorConic::Shape;

// −1, 0, 1 as a Sign.
int as_int(Sign s) { return static_cast<int>(s); }

}  // namespace

BisectorConic::BisectorConic(const MetricSite& v, const MetricSite& w) : v_(v), w_(w) {
  // Once per conic, exactly.
  const auto of = [](double x) { return Rational(x); };
  const ConicIn<Rational> q = bisector_coefficients(lift<Rational>(v, of), lift<Rational>(w, of));
  if (q.a == 0 && q.b == 0 && q.c == 0) {
    shape_ = q.d == 0 && q.e == 0 ? Shape::degenerate : Shape::line;
    return;
  }
  // det [2a b d; b 2c e; d e 2f], 8 times the determinant of the conic's symmetric matrix: zero
  // for a line pair, a double line, a point or nothing.
  const Rational det = 2 * q.a * (4 * q.c * q.f - q.e * q.e) - q.b * (2 * q.b * q.f - q.d * q.e) + q.d * (q.b * q.e - 2 * q.c * q.d);
  if (det == 0) return;  // degenerate
  const Rational L = q.b * q.b - 4 * q.a * q.c, K = 2 * q.b * q.e - 4 * q.c * q.d, C = q.e * q.e - 4 * q.c * q.f;
  if (L < 0) {
    shape_ = Shape::ellipse;
  } else if (L > 0) {
    if (q.c == 0) shape_ = Shape::hyperbola_vertical_asymptote;
    else shape_ = sign_of(4 * L * C - K * K) == Sign::negative ? Shape::hyperbola_two_ranges : Shape::hyperbola_two_branches;
  } else {
    shape_ = q.c == 0 ? Shape::parabola_graph : Shape::parabola;
    k_sign_ = as_int(sign_of(K));
  }
}

std::optional<BisectorConic::Piece> BisectorConic::piece(const CertifiedPoint& p) const {
  if (shape_ == Shape::line) return Piece{};
  const auto sigma = sign_at<1>({&p}, [&](const auto& P, auto of) {
    using T = std::decay_t<decltype(P[0].x)>;
    const ConicIn<T> q = bisector_coefficients(lift<T>(v_, of), lift<T>(w_, of));
    return q.b * P[0].x + (q.c + q.c) * P[0].y + q.e;  // ∂B/∂y
  });
  if (!sigma || *sigma == Sign::zero) return std::nullopt;
  Piece out{as_int(*sigma), 0};
  if (shape_ == Shape::hyperbola_two_ranges) {
    const auto side = sign_at<1>({&p}, [&](const auto& P, auto of) {
      using T = std::decay_t<decltype(P[0].x)>;
      const ConicIn<T> q = bisector_coefficients(lift<T>(v_, of), lift<T>(w_, of));
      const T L = q.b * q.b - (q.a * q.c + q.a * q.c + q.a * q.c + q.a * q.c), K = (q.b * q.e + q.b * q.e) - (q.c * q.d + q.c * q.d + q.c * q.d + q.c * q.d);
      return (L + L) * P[0].x + K;  // 2L(x − x*), L > 0
    });
    if (!side || *side == Sign::zero) return std::nullopt;
    out.side = as_int(*side);
  }
  return out;
}

bool BisectorConic::turns(const Piece& p) const {
  switch (shape_) {
    case Shape::ellipse: return true;
    case Shape::hyperbola_two_ranges: return p.sigma == p.side;  // travel −σ points towards x*
    case Shape::parabola: return p.sigma == k_sign_;             // the tangent lies towards −sign K
    default: return false;
  }
}

std::optional<int> BisectorConic::first_after(const CertifiedPoint& p, std::span<const CertifiedPoint* const> candidates) const {
  const int n = static_cast<int>(candidates.size());
  if (shape_ == Shape::degenerate) return std::nullopt;
  // key(A) − key(B) along a direction: lines by −e x + d y, pieces by s·x.
  const auto compare = [&](const CertifiedPoint& A, const CertifiedPoint& B, int s) {
    return sign_at<2>({&A, &B}, [&](const auto& P, auto of) {
      using T = std::decay_t<decltype(P[0].x)>;
      if (shape_ == Shape::line) {
        const ConicIn<T> q = bisector_coefficients(lift<T>(v_, of), lift<T>(w_, of));
        return q.d * (P[0].y - P[1].y) - q.e * (P[0].x - P[1].x);
      }
      const T dx = P[0].x - P[1].x;
      return s > 0 ? dx : -dx;
    });
  };
  const auto p_piece = piece(p);
  if (!p_piece) return std::nullopt;
  std::vector<Piece> pieces(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const auto q = piece(*candidates[static_cast<std::size_t>(i)]);
    if (!q) return std::nullopt;
    pieces[static_cast<std::size_t>(i)] = *q;
  }
  // The least candidate by key s·x (or along the line) among those of `piece` that pass `keep`;
  // −1 when there is none, nothing when undecided.
  bool undecided = false;
  const auto least = [&](const Piece& on, int s, auto keep) {
    int best = -1;
    for (int i = 0; i < n && !undecided; ++i) {
      if (!(pieces[static_cast<std::size_t>(i)] == on)) continue;
      const std::optional<bool> kept = keep(i);
      if (!kept) undecided = true;
      if (!kept || !*kept) continue;
      if (best < 0) {
        best = i;
        continue;
      }
      const auto c = compare(*candidates[static_cast<std::size_t>(i)], *candidates[static_cast<std::size_t>(best)], s);
      if (!c || *c == Sign::zero) undecided = true;  // distinct points of one piece differ in x
      else if (*c == Sign::negative) best = i;
    }
    return best;
  };
  const int s = shape_ == Shape::line ? 1 : -p_piece->sigma;  // travel direction in x (lines: along the key)
  const auto ahead = [&](int i) -> std::optional<bool> {
    const auto c = compare(*candidates[static_cast<std::size_t>(i)], p, s);
    if (!c || *c == Sign::zero) return std::nullopt;
    return *c == Sign::positive;
  };
  // Stage 0: ahead of p on its piece, the nearest.
  int first = least(*p_piece, s, ahead);
  if (undecided) return std::nullopt;
  if (first >= 0 || !turns(*p_piece)) return first;
  // Stage 1: round the vertical tangent onto the partner piece, run in x-direction −s: first the
  // candidate nearest the tangent, the most extreme in direction s (the least by −s·x).
  const Piece partner{-p_piece->sigma, p_piece->side};
  first = least(partner, -s, [](int) -> std::optional<bool> { return true; });
  if (undecided) return std::nullopt;
  if (first >= 0 || shape_ != Shape::ellipse) return first;
  // Stage 2 (a closed curve): round the other tangent back onto p's piece, entering from its far
  // end: the candidates behind p, the most extreme in direction −s first.
  first = least(*p_piece, s, [&](int i) -> std::optional<bool> {
    const auto a = ahead(i);
    if (!a) return std::nullopt;
    return !*a;
  });
  if (undecided) return std::nullopt;
  return first;
}

}  // namespace anisocert::refiners::common
