#include "oracle/algebraic/algebraic_point.hpp"

#include <stdexcept>

namespace anisocert::oracle {
namespace {

// [a, b] / [c, d] for 0 ∉ [c, d], exact.
std::pair<Rational, Rational> quotient(const std::pair<Rational, Rational>& n, const std::pair<Rational, Rational>& d) {
  const Rational q[4] = {n.first / d.first, n.first / d.second, n.second / d.first, n.second / d.second};
  Rational lo = q[0], hi = q[0];
  for (const Rational& v : q) lo = v < lo ? v : lo, hi = v > hi ? v : hi;
  return {lo, hi};
}

Sign power_sign(Sign s, int k) { return k % 2 == 0 ? Sign::positive : s; }

}  // namespace

AlgebraicPoint::AlgebraicPoint(RealAlgebraic u, Polynomial x_num, Polynomial x_den, Polynomial y_num, Polynomial y_den,
                               Polynomial x_defining, Polynomial y_defining)
    : u_(std::move(u)),
      xn_(std::move(x_num)),
      xd_(std::move(x_den)),
      yn_(std::move(y_num)),
      yd_(std::move(y_den)),
      xdef_(squarefree_part(x_defining)),
      ydef_(squarefree_part(y_defining)) {
  if (u_.sign_of(xd_) == Sign::zero || u_.sign_of(yd_) == Sign::zero)
    throw std::invalid_argument("AlgebraicPoint: a coordinate denominator vanishes at the parameter");
}

AlgebraicPoint AlgebraicPoint::rational(const Rational& x, const Rational& y) {
  const Polynomial one = Polynomial::constant(1);
  return AlgebraicPoint(RealAlgebraic::rational(0), Polynomial::constant(x), one, Polynomial::constant(y), one,
                        Polynomial(std::vector<Rational>{-x, 1}), Polynomial(std::vector<Rational>{-y, 1}));
}

std::vector<AlgebraicPoint> AlgebraicPoint::on_conic_at(const Conic& C, const Rational& x0) {
  // C(x0, y) = c y² + (b x0 + e) y + (a x0² + d x0 + f)
  const Polynomial q(std::vector<Rational>{C.a * x0 * x0 + C.d * x0 + C.f, C.b * x0 + C.e, C.c});
  if (q.is_zero()) throw std::invalid_argument("on_conic_at: the conic contains the whole line x = x0");
  std::vector<AlgebraicPoint> points;
  if (q.degree() < 1) return points;
  const Polynomial one = Polynomial::constant(1);
  for (RealAlgebraic& y : real_roots(q))
    points.emplace_back(y, Polynomial::constant(x0), one, Polynomial::x(), one,
                        Polynomial(std::vector<Rational>{-x0, 1}), q);
  return points;
}

RealAlgebraic AlgebraicPoint::coordinate(const Polynomial& defining, const Polynomial& num, const Polynomial& den) const {
  // Convergence is certain when `defining` vanishes at the coordinate (it does: it is a
  // resultant in the ideal of the two conics). The number of halvings needed grows like the
  // bit size of the root separation, bounded by a multiple of the coefficients' bit sizes; the
  // cap below is far above that and only turns a bug into an error instead of a hang.
  const std::vector<Polynomial> sturm = sturm_sequence(defining);
  std::size_t bits = 0;
  for (const Rational& c : defining.coefficients())
    bits += boost::multiprecision::numerator(c).str().size() + boost::multiprecision::denominator(c).str().size();
  const std::size_t cap = 100000 + 100 * bits * static_cast<std::size_t>(defining.degree() + 1);
  for (std::size_t step = 0; step < cap; ++step) {
    if (u_.is_exact()) return RealAlgebraic::rational(num(u_.lo()) / den(u_.lo()));
    const auto d = den.range(u_.lo(), u_.hi());
    if (d.first > 0 || d.second < 0) {
      const auto [lo, hi] = quotient(num.range(u_.lo(), u_.hi()), d);
      if (lo == hi) return RealAlgebraic::rational(lo);  // the coordinate map is constant here
      // The enclosure holds the coordinate, a root of `defining`; once it holds no other root
      // and its ends are not roots, it isolates it.
      if (lo < hi && defining.sign_at(lo) != Sign::zero && defining.sign_at(hi) != Sign::zero &&
          count_roots(sturm, lo, hi) == 1)
        return RealAlgebraic(defining, lo, hi);
    }
    u_.refine();
  }
  throw std::logic_error("AlgebraicPoint: a coordinate does not isolate as a root of its defining polynomial");
}

const RealAlgebraic& AlgebraicPoint::x() const {
  if (!x_) x_ = coordinate(xdef_, xn_, xd_);
  return *x_;
}

const RealAlgebraic& AlgebraicPoint::y() const {
  if (!y_) y_ = coordinate(ydef_, yn_, yd_);
  return *y_;
}

Sign AlgebraicPoint::sign_of(const Bivariate& P) const {
  // P(xn/xd, yn/yd) · xd^dx · yd^dy = Σ c_ij xn^i xd^(dx−i) yn^j yd^(dy−j) =: N(u)
  if (P.is_zero()) return Sign::zero;
  const int dx = P.degree_x(), dy = P.degree_y();
  Polynomial N;
  for (const auto& [ij, c] : P.terms)
    N = N + c * (power(xn_, ij.first) * power(xd_, dx - ij.first) * power(yn_, ij.second) * power(yd_, dy - ij.second));
  return u_.sign_of(N) * power_sign(u_.sign_of(xd_), dx) * power_sign(u_.sign_of(yd_), dy);
}

Sign compare_x(const AlgebraicPoint& p, const AlgebraicPoint& q) { return compare(p.x(), q.x()); }
Sign compare_y(const AlgebraicPoint& p, const AlgebraicPoint& q) { return compare(p.y(), q.y()); }
bool same_point(const AlgebraicPoint& p, const AlgebraicPoint& q) {
  return compare_x(p, q) == Sign::zero && compare_y(p, q) == Sign::zero;
}

}  // namespace anisocert::oracle
