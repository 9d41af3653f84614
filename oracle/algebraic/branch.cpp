#include "oracle/algebraic/branch.hpp"

#include <stdexcept>

namespace anisocert::oracle {

bool is_line(const Conic& G) { return G.a == 0 && G.b == 0 && G.c == 0; }

Polynomial discriminant_in_x(const Conic& G) {
  if (is_line(G)) return Polynomial();
  const Polynomial be(std::vector<Rational>{G.e, G.b});
  return be * be - 4 * G.c * Polynomial(std::vector<Rational>{G.f, G.d, G.a});
}

Conic derivative_in_y(const Conic& G) { return {0, 0, 0, G.b, 2 * G.c, G.e}; }

bool Branch::holds(const LocatedPoint& p) const {
  if (side == 0) return true;
  const Sign L = p.sign_of(derivative_in_y(curve));
  const int s = static_cast<int>(L) * (curve.c > 0 ? 1 : -1);
  return s == 0 || s == side;
}

Sign Branch::compare_point(const LocatedPoint& p) const {
  const Sign g = p.sign_of(curve);
  if (side == 0) return curve.e > 0 ? g : -g;  // G = e·(y − y_line)
  const int sc = curve.c > 0 ? 1 : -1;
  const int sg = static_cast<int>(g) * sc;  // sign of (y − y₋)(y − y₊)
  const int sl = static_cast<int>(p.sign_of(derivative_in_y(curve))) * sc;  // sign of y − (y₋ + y₊)/2
  if (sg < 0) return side > 0 ? Sign::negative : Sign::positive;  // strictly between the roots
  if (sg == 0) {  // on a root: the upper one when sl > 0, the lower one when sl < 0, both when 0
    if (sl == 0 || sl == side) return Sign::zero;
    return sl > 0 ? Sign::positive : Sign::negative;
  }
  return sl > 0 ? Sign::positive : Sign::negative;  // outside both roots
}

LocatedPoint Branch::at(const Rational& x0, const Rational& width) const {
  if (side == 0) return LocatedPoint::rational(x0, -(curve.d * x0 + curve.f) / curve.e);
  std::vector<AlgebraicPoint> roots = AlgebraicPoint::on_conic_at(curve, x0);
  if (roots.size() != 2) throw std::logic_error("Branch::at: x0 is not inside the branch's x-domain");
  return LocatedPoint(side > 0 ? roots[1] : roots[0], width);
}

int Branch::positive_side() const {
  if (side == 0) return curve.e > 0 ? 1 : -1;
  // Above the upper root and below the lower one G has the sign of c; between them the other.
  return (curve.c > 0 ? 1 : -1) * side;
}

Rational rational_between(const RealAlgebraic& a, const RealAlgebraic& b) {
  while (!(a.hi() < b.lo())) {
    if (a.hi() - a.lo() >= b.hi() - b.lo()) a.refine(); else b.refine();
    if (a.is_exact() && b.is_exact() && a.lo() >= b.lo())
      throw std::logic_error("rational_between: the numbers are not increasing");
  }
  return (a.hi() + b.lo()) / 2;
}

}  // namespace anisocert::oracle
