#pragma once
// Univariate polynomials with exact rational coefficients: the arithmetic behind the exact
// algebraic points of the oracle (Voronoi vertices are common roots of two bisector conics,
// algebraic of degree <= 4; DESIGN.md § Numbers and exactness).

#include "numbers/rational.hpp"
#include "numbers/sign.hpp"

#include <utility>
#include <vector>

namespace anisocert::oracle {


class Polynomial {
 public:
  Polynomial() = default;  // the zero polynomial
  explicit Polynomial(std::vector<Rational> coefficients);  // c₀ + c₁x + …, trailing zeros dropped
  static Polynomial constant(const Rational& c);
  static Polynomial x();

  int degree() const { return static_cast<int>(c_.size()) - 1; }  // −1 for zero
  bool is_zero() const { return c_.empty(); }
  Rational coefficient(int i) const;
  const Rational& leading() const { return c_.back(); }
  const std::vector<Rational>& coefficients() const { return c_; }

  Rational operator()(const Rational& x) const;  // Horner, exact
  // sign(p(x)), exact, in integer arithmetic: for x = a/b (b > 0) and p = P/L with P integral
  // and L > 0, sign p(x) = sign Σ P_i a^i b^(d−i) (no rational normalisation, no gcds).
  Sign sign_at(const Rational& x) const;
  // Exact enclosure of the values on [lo, hi] (rational interval arithmetic, Horner).
  std::pair<Rational, Rational> range(const Rational& lo, const Rational& hi) const;

  Polynomial derivative() const;
  Polynomial monic() const;  // zero stays zero

  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Rational& s, const Polynomial& a);
  friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.c_ == b.c_; }

 private:
  void trim();
  std::vector<Rational> c_;
  mutable std::vector<Integer> integral_;  // P, computed on first use
};

// a = q b + r, deg r < deg b; b non-zero.
std::pair<Polynomial, Polynomial> divide(const Polynomial& a, const Polynomial& b);
// The monic greatest common divisor (zero only if both are zero).
Polynomial gcd(const Polynomial& a, const Polynomial& b);
// p / gcd(p, p'): the same roots, each simple (monic).
Polynomial squarefree_part(const Polynomial& p);
// p^k
Polynomial power(const Polynomial& p, int k);

}  // namespace anisocert::oracle
