#include "predicates/metric.hpp"

#include "numbers/excerpt.hpp"

#include <string>

namespace anisocert::predicates {
namespace {

std::string show(const Sym2<Rational>& m) {
  return "[" + exact_excerpt(m.m11) + ", " + exact_excerpt(m.m12) + ", " + exact_excerpt(m.m22) + "]";
}
std::string show(const Sym3<Rational>& m) {
  return "[" + exact_excerpt(m.m11) + ", " + exact_excerpt(m.m12) + ", " + exact_excerpt(m.m13) + ", " +
         exact_excerpt(m.m22) + ", " + exact_excerpt(m.m23) + ", " + exact_excerpt(m.m33) + "]";
}

void require_positive(const Rational& pivot, const std::string& matrix, const std::string& what) {
  if (!(pivot > 0))
    throw NotPositiveDefinite("metric " + matrix + " is not positive definite: " + what + " = " +
                              exact_excerpt(pivot) + " is not > 0");
}

// q = r^k for a rational r: exact integer k-th roots of numerator and denominator.
std::optional<Rational> exact_root(const Rational& q, unsigned k) {
  if (q <= 0) return std::nullopt;
  Integer num = boost::multiprecision::numerator(q), den = boost::multiprecision::denominator(q);
  Integer rn, rd;
  mpz_root(rn.backend().data(), num.backend().data(), k);
  mpz_root(rd.backend().data(), den.backend().data(), k);
  if (boost::multiprecision::pow(rn, k) != num || boost::multiprecision::pow(rd, k) != den) return std::nullopt;
  return Rational(rn, rd);
}

}  // namespace

Rational determinant(const Sym3<Rational>& m) {
  return m.m11 * (m.m22 * m.m33 - m.m23 * m.m23) - m.m12 * (m.m12 * m.m33 - m.m23 * m.m13) + m.m13 * (m.m12 * m.m23 - m.m22 * m.m13);
}

// Sylvester's criterion, i.e. the pivots of LDLᵀ are positive.
Metric2::Metric2(const Sym2<Rational>& m) : m_(m) {
  require_positive(m.m11, show(m), "m11");
  require_positive(determinant(), show(m), "det = m11·m22 − m12²");
}

Metric2 Metric2::from_doubles(double m11, double m12, double m22) {
  return Metric2(Sym2<Rational>{rational_from_double(m11), rational_from_double(m12), rational_from_double(m22)});
}

Rational Metric2::determinant() const { return m_.m11 * m_.m22 - m_.m12 * m_.m12; }

bool positive_definite(const Sym2<Rational>& m) { return m.m11 > 0 && m.m11 * m.m22 - m.m12 * m.m12 > 0; }

bool positive_definite(const Sym3<Rational>& m) {
  return m.m11 > 0 && m.m11 * m.m22 - m.m12 * m.m12 > 0 && determinant(m) > 0;
}

LDLt2 Metric2::ldlt() const {
  return {m_.m12 / m_.m11, m_.m11, determinant() / m_.m11};
}

Rational Metric2::quadratic_form(const Rational& dx, const Rational& dy) const {
  return predicates::quadratic_form(m_.m11, m_.m12, m_.m22, dx, dy);
}

std::optional<Metric2> Metric2::normalized() const {
  const std::optional<Rational> root = exact_root(determinant(), 2);
  if (!root) return std::nullopt;
  return Metric2(Sym2<Rational>{m_.m11 / *root, m_.m12 / *root, m_.m22 / *root});
}

Metric3::Metric3(const Sym3<Rational>& m) : m_(m) {
  const std::string s = show(m);
  require_positive(m.m11, s, "m11");
  require_positive(m.m11 * m.m22 - m.m12 * m.m12, s, "the 2x2 leading minor m11·m22 − m12²");
  require_positive(determinant(), s, "det");
}

Rational Metric3::determinant() const { return predicates::determinant(m_); }

LDLt3 Metric3::ldlt() const {
  const Sym3<Rational>& m = m_;
  LDLt3 f;
  f.d1 = m.m11;
  f.l21 = m.m12 / f.d1;
  f.l31 = m.m13 / f.d1;
  f.d2 = m.m22 - f.l21 * f.l21 * f.d1;
  f.l32 = (m.m23 - f.l31 * f.l21 * f.d1) / f.d2;
  f.d3 = m.m33 - f.l31 * f.l31 * f.d1 - f.l32 * f.l32 * f.d2;
  return f;
}

Rational Metric3::quadratic_form(const Rational& x, const Rational& y, const Rational& z) const {
  const Sym3<Rational>& m = m_;
  return x * (m.m11 * x + m.m12 * y + m.m13 * z) + y * (m.m12 * x + m.m22 * y + m.m23 * z) +
         z * (m.m13 * x + m.m23 * y + m.m33 * z);
}

std::optional<Metric3> Metric3::normalized() const {
  const std::optional<Rational> root = exact_root(determinant(), 3);
  if (!root) return std::nullopt;
  const Sym3<Rational>& m = m_;
  return Metric3(Sym3<Rational>{m.m11 / *root, m.m12 / *root, m.m13 / *root, m.m22 / *root, m.m23 / *root,
                                m.m33 / *root});
}

Sign side_of_normalized_bisector(const Point2<Rational>& q, const Point2<Rational>& v, const Metric2& Mv,
                                 const Point2<Rational>& w, const Metric2& Mw) {
  const Rational Qv = Mv.quadratic_form(q.x - v.x, q.y - v.y), Qw = Mw.quadratic_form(q.x - w.x, q.y - w.y);
  return sign_of(Qv * Qv * Mw.determinant() - Qw * Qw * Mv.determinant());
}

}  // namespace anisocert::predicates
