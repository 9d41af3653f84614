#include "oracle/algebraic/shared_line.hpp"

#include "oracle/algebraic/branch.hpp"
#include "oracle/algebraic/polynomial.hpp"

#include <stdexcept>

namespace anisocert::oracle {

Conic line_quotient(const Conic& F, const Conic& L) {
  if (is_line(F)) return {0, 0, 0, 0, 0, F.e / L.e};
  const Rational q = F.c / L.e, p = (F.b - L.d * q) / L.e, r = (F.e - L.f * q) / L.e;
  return {0, 0, 0, p, q, r};
}

std::optional<Conic> common_line(const Conic& A, const Conic& B) {
  std::vector<predicates::Point2<Rational>> on;
  for (int t = 0; t < 8 && on.size() < 2; ++t) {
    const Rational x(t * 3 + 1, 7);
    auto restrict = [&](const Conic& C) {
      return Polynomial(std::vector<Rational>{C.a * x * x + C.d * x + C.f, C.b * x + C.e, C.c});
    };
    const Polynomial g = gcd(restrict(A), restrict(B));
    if (g.degree() == 1) on.push_back({x, -g.coefficient(0) / g.coefficient(1)});
  }
  if (on.size() < 2) return std::nullopt;
  return line_conic(on[0], on[1]);
}
std::vector<AlgebraicPoint> isolated_common_points(const Conic& A, const Conic& B) {
  std::vector<AlgebraicPoint> out;
  const ConicIntersection x = intersect(A, B);
  if (!x.shared_component) {
    for (const IntersectionPoint& p : x.points) out.push_back(p.point);
    return out;
  }
  const std::optional<Conic> G = common_line(A, B);
  if (!G) {
    // Non-proportional conics can only share a line, and a rational one (its conjugate would be
    // shared too); common_line misses it only when H1 = H2, i.e. when A and B are proportional.
    const Rational a[6] = {A.a, A.b, A.c, A.d, A.e, A.f}, b[6] = {B.a, B.b, B.c, B.d, B.e, B.f};
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j)
        if (a[i] * b[j] != a[j] * b[i]) throw std::domain_error("two conics share a component that common_line does not find");
    return out;  // proportional: every common point lies on the shared curve
  }
  const Conic H1 = line_quotient(A, *G), H2 = line_quotient(B, *G);
  if ((H1.d == 0 && H1.e == 0) || (H2.d == 0 && H2.e == 0)) return out;  // A or B is G itself
  const ConicIntersection h = intersect(H1, H2);
  if (h.shared_component) return out;  // H1 = H2: A and B are proportional
  for (const IntersectionPoint& p : h.points)
    if (p.point.sign_of(G->polynomial()) != Sign::zero) out.push_back(p.point);
  return out;
}

}  // namespace anisocert::oracle
