#include "oracle/algebraic/polynomial.hpp"

#include <stdexcept>

namespace anisocert::oracle {

Polynomial::Polynomial(std::vector<Rational> coefficients) : c_(std::move(coefficients)) { trim(); }

void Polynomial::trim() {
  while (!c_.empty() && c_.back() == 0) c_.pop_back();
}

Polynomial Polynomial::constant(const Rational& c) { return Polynomial(std::vector<Rational>{c}); }
Polynomial Polynomial::x() { return Polynomial(std::vector<Rational>{0, 1}); }

Rational Polynomial::coefficient(int i) const { return i >= 0 && i <= degree() ? c_[i] : Rational(0); }

Rational Polynomial::operator()(const Rational& x) const {
  Rational v = 0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) v = v * x + *it;
  return v;
}

Sign Polynomial::sign_at(const Rational& x) const {
  if (c_.empty()) return Sign::zero;
  if (integral_.empty()) {
    Integer L = 1;
    for (const Rational& c : c_) L = boost::multiprecision::lcm(L, boost::multiprecision::denominator(c));
    for (const Rational& c : c_) integral_.push_back(boost::multiprecision::numerator(c) * (L / boost::multiprecision::denominator(c)));
  }
  const Integer a = boost::multiprecision::numerator(x), b = boost::multiprecision::denominator(x);
  Integer v = integral_.back(), power = 1;
  for (std::size_t i = integral_.size() - 1; i-- > 0;) {
    power *= b;
    v = v * a + integral_[i] * power;
  }
  return anisocert::sign_of(Rational(v));
}

std::pair<Rational, Rational> Polynomial::range(const Rational& lo, const Rational& hi) const {
  Rational vlo = 0, vhi = 0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) {
    // [vlo, vhi] · [lo, hi] + c
    const Rational p[4] = {vlo * lo, vlo * hi, vhi * lo, vhi * hi};
    Rational mn = p[0], mx = p[0];
    for (const Rational& q : p) mn = q < mn ? q : mn, mx = q > mx ? q : mx;
    vlo = mn + *it;
    vhi = mx + *it;
  }
  return {vlo, vhi};
}

Polynomial Polynomial::derivative() const {
  std::vector<Rational> d;
  for (int i = 1; i <= degree(); ++i) d.push_back(c_[i] * i);
  return Polynomial(std::move(d));
}

Polynomial Polynomial::monic() const {
  if (is_zero()) return *this;
  const Rational l = leading();
  std::vector<Rational> m = c_;
  for (Rational& c : m) c /= l;
  return Polynomial(std::move(m));
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  std::vector<Rational> r(std::max(a.c_.size(), b.c_.size()));
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = a.coefficient(int(i)) + b.coefficient(int(i));
  return Polynomial(std::move(r));
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) { return a + Rational(-1) * b; }

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<Rational> r(a.c_.size() + b.c_.size() - 1);
  for (std::size_t i = 0; i < a.c_.size(); ++i)
    for (std::size_t j = 0; j < b.c_.size(); ++j) r[i + j] += a.c_[i] * b.c_[j];
  return Polynomial(std::move(r));
}

Polynomial operator*(const Rational& s, const Polynomial& a) {
  std::vector<Rational> r = a.c_;
  for (Rational& c : r) c *= s;
  return Polynomial(std::move(r));
}

std::pair<Polynomial, Polynomial> divide(const Polynomial& a, const Polynomial& b) {
  if (b.is_zero()) throw std::domain_error("polynomial division by zero");
  std::vector<Rational> q(std::max(0, a.degree() - b.degree() + 1));
  std::vector<Rational> r = a.coefficients();
  for (int k = a.degree() - b.degree(); k >= 0; --k) {
    const Rational f = r[k + b.degree()] / b.leading();
    q[k] = f;
    for (int j = 0; j <= b.degree(); ++j) r[k + j] -= f * b.coefficient(j);
  }
  return {Polynomial(std::move(q)), Polynomial(std::move(r))};
}

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  Polynomial x = a, y = b;
  while (!y.is_zero()) {
    Polynomial r = divide(x, y).second;
    x = std::move(y);
    y = std::move(r);
  }
  return x.monic();
}

Polynomial squarefree_part(const Polynomial& p) {
  if (p.degree() <= 0) return p.monic();
  return divide(p, gcd(p, p.derivative())).first.monic();
}

Polynomial power(const Polynomial& p, int k) {
  Polynomial r = Polynomial::constant(1);
  for (int i = 0; i < k; ++i) r = r * p;
  return r;
}

}  // namespace anisocert::oracle
