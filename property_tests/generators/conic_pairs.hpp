#pragma once
// Pairs of conics that reach the degenerate cases of an intersection, built exactly from points
// and lines: shared by the property Oracle.ConicIntersectionAgreesWithQqbar (random rationals)
// and the fuzz harness conics_second_engine (small integers from bytes). No RapidCheck here.
#include "oracle/algebraic/bivariate.hpp"

#include <array>
#include <utility>

namespace anisocert::gen {

using RPoint = std::pair<Rational, Rational>;
using Line = std::array<Rational, 3>;  // l0 x + l1 y + l2
using ConicPair = std::pair<oracle::Conic, oracle::Conic>;

// The line through p and q: (y_q − y_p) x − (x_q − x_p) y + (x_q y_p − x_p y_q).
inline Line line(const RPoint& p, const RPoint& q) {
  return {q.second - p.second, p.first - q.first, q.first * p.second - p.first * q.second};
}
inline oracle::Conic product(const Line& l, const Line& m) {
  return {l[0] * m[0], l[0] * m[1] + l[1] * m[0], l[1] * m[1], l[0] * m[2] + l[2] * m[0], l[1] * m[2] + l[2] * m[1],
          l[2] * m[2]};
}
inline oracle::Conic combine(const oracle::Conic& P, const Rational& s, const oracle::Conic& Q) {
  return {P.a + s * Q.a, P.b + s * Q.b, P.c + s * Q.c, P.d + s * Q.d, P.e + s * Q.e, P.f + s * Q.f};
}

// Two members of the pencil through four points, L₁L₂ + λ L₃L₄ and L₁L₂ + μ L₃L₄.
inline ConicPair through_four_points(const RPoint& p1, const RPoint& p2, const RPoint& p3, const RPoint& p4,
                                     const Rational& l, const Rational& m) {
  const oracle::Conic Q1 = product(line(p1, p2), line(p3, p4)), Q2 = product(line(p1, p3), line(p2, p4));
  return {combine(Q1, l, Q2), combine(Q1, m, Q2)};
}

// A moved through p and B = A + λ T² with T its tangent line at p (λ = 0 taken as 1): a double point.
inline ConicPair tangent_at(oracle::Conic A, const RPoint& p, const Rational& l) {
  const auto& [x, y] = p;
  A.f -= A(x, y);
  const Rational gx = 2 * A.a * x + A.b * y + A.d, gy = A.b * x + 2 * A.c * y + A.e;
  const Line T{gx, gy, -(gx * x + gy * y)};
  return {A, combine(A, l == 0 ? Rational(1) : l, product(T, T))};
}

// Two line pairs sharing the line pq: a shared component.
inline ConicPair sharing_a_line(const RPoint& p, const RPoint& q, const RPoint& r, const RPoint& s, const RPoint& t) {
  const Line L = line(p, q);
  return {product(L, line(r, s)), product(L, line(s, t))};
}

// Two line pairs through o: a point singular for both.
inline ConicPair singular_at(const RPoint& o, const RPoint& p, const RPoint& q, const RPoint& r, const RPoint& s) {
  return {product(line(o, p), line(o, q)), product(line(o, r), line(o, s))};
}

}  // namespace anisocert::gen
