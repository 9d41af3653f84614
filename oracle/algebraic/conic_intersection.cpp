#include "oracle/algebraic/conic_intersection.hpp"

#include <algorithm>
#include <stdexcept>

namespace anisocert::oracle {
namespace {

// A(u − t y, y) = α₂ y² + α₁(u) y + α₀(u):
//   α₂ = a t² − b t + c,  α₁ = (b − 2 a t) u + (e − d t),  α₀ = a u² + d u + f.
struct InY {
  Polynomial c2, c1, c0;
  int degree() const { return !c2.is_zero() ? 2 : !c1.is_zero() ? 1 : 0; }
};

InY sheared(const Conic& C, const Rational& t) {
  return {Polynomial::constant(C.a * t * t - C.b * t + C.c),
          Polynomial(std::vector<Rational>{C.e - C.d * t, C.b - 2 * C.a * t}),
          Polynomial(std::vector<Rational>{C.f, C.d, C.a})};
}

Polynomial resultant(const InY& A, const InY& B) {
  const int da = A.degree(), db = B.degree();
  if (da == 2 && db == 2)
    return power(A.c2 * B.c0 - A.c0 * B.c2, 2) - (A.c2 * B.c1 - A.c1 * B.c2) * (A.c1 * B.c0 - A.c0 * B.c1);
  if (da == 2 && db == 1) return A.c2 * power(B.c0, 2) - A.c1 * B.c0 * B.c1 + A.c0 * power(B.c1, 2);
  if (da == 1 && db == 2) return B.c2 * power(A.c0, 2) - B.c1 * A.c0 * A.c1 + B.c0 * power(A.c1, 2);
  if (da == 1 && db == 1) return A.c1 * B.c0 - A.c0 * B.c1;
  if (da == 0 && db == 0) return gcd(A.c0, B.c0).degree() >= 1 ? Polynomial() : Polynomial::constant(1);
  return da == 0 ? power(A.c0, db) : power(B.c0, da);
}

// (s₀, s₁) with the common root y = −s₀/s₁ in a fibre where the gcd is linear.
std::pair<Polynomial, Polynomial> linear_gcd(const InY& A, const InY& B) {
  if (A.degree() == 2 && B.degree() == 2) return {A.c2 * B.c0 - A.c0 * B.c2, A.c2 * B.c1 - A.c1 * B.c2};
  if (B.degree() == 1) return {B.c0, B.c1};
  return {A.c0, A.c1};
}

std::vector<Rational> shear_candidates() {
  std::vector<Rational> t{0};
  for (int n = 1; n <= 12; ++n)
    for (int d = 1; d <= 5; ++d) t.push_back(Rational(n, d)), t.push_back(Rational(-n, d));
  return t;
}

}  // namespace

Polynomial sheared_resultant(const Conic& A, const Conic& B, const Rational& t) {
  return resultant(sheared(A, t), sheared(B, t));
}

ConicIntersection intersect(const Conic& A, const Conic& B) {
  const auto all_zero = [](const Conic& C) { return C.degree() == 0 && C.f == 0; };
  if (all_zero(A) || all_zero(B)) throw std::invalid_argument("a conic with all coefficients zero is the whole plane");
  ConicIntersection result;
  if (A.degree() == 0 || B.degree() == 0) return result;  // a non-zero constant: no points
  for (const Rational& t : shear_candidates()) {
    const InY a = sheared(A, t), b = sheared(B, t);
    if (a.degree() != A.degree() || b.degree() != B.degree()) continue;  // (i) fails for this t
    const Polynomial R = resultant(a, b);
    if (R.is_zero()) {
      result.shared_component = true;
      return result;
    }
    // Fibres where s₁ ≠ 0 hold one common point, y = −s₀/s₁. Where s₁ = 0 (both conics of degree 2
    // in y), the fibre holds one point only if both restrictions have a double root there (both
    // discriminants vanish, e.g. at a point singular on both conics); then y = −α₁/(2α₂).
    const auto [s0, s1] = linear_gcd(a, b);
    const Polynomial roots = squarefree_part(R);
    const Polynomial G = gcd(roots, s1);
    const auto vanishes_on_G = [&G](const InY& C) {
      return divide(C.c1 * C.c1 - Rational(4) * (C.c2 * C.c0), G).second.is_zero();
    };
    if (G.degree() >= 1 && !(vanishes_on_G(a) && vanishes_on_G(b))) continue;  // (ii) fails for this t
    const Polynomial xdef = sheared_resultant(A, B, 0), ydef = sheared_resultant(A.swapped(), B.swapped(), 0);
    const auto add_points = [&](const Polynomial& factor, const Polynomial& num, const Polynomial& den) {
      if (factor.degree() < 1) return;
      // y = num/den, x = u − t y = (u den − t num)/den.
      const Polynomial xn = Polynomial::x() * den - t * num;
      for (RealAlgebraic& u : real_roots(factor))
        result.points.push_back({AlgebraicPoint(u, xn, den, num, den, xdef, ydef), multiplicity(u, R)});
    };
    add_points(divide(roots, G).first, Rational(-1) * s0, s1);
    add_points(G, Rational(-1) * a.c1, Rational(2) * a.c2);
    std::sort(result.points.begin(), result.points.end(), [](const IntersectionPoint& p, const IntersectionPoint& q) {
      const Sign sx = compare_x(p.point, q.point);
      return sx != Sign::zero ? sx == Sign::negative : compare_y(p.point, q.point) == Sign::negative;
    });
    return result;
  }
  throw std::logic_error("intersect: no generic shear among the candidates");
}

}  // namespace anisocert::oracle
