#pragma once
// Bivariate polynomials with rational coefficients, Σ c_ij x^i y^j; conics as their
// special case a x² + b xy + c y² + d x + e y + f (LS Proposition 2: bisectors are conics).

#include "numbers/rational.hpp"
#include "predicates/point.hpp"

#include <map>
#include <utility>

namespace anisocert::oracle {

struct Bivariate {
  std::map<std::pair<int, int>, Rational> terms;  // (i, j) ↦ c_ij, no zero entries
  Bivariate& add(int i, int j, const Rational& c);
  int degree_x() const;
  int degree_y() const;
  bool is_zero() const { return terms.empty(); }
};

struct Conic {
  Rational a, b, c, d, e, f;
  Bivariate polynomial() const;
  Conic swapped() const { return {c, b, a, e, d, f}; }  // x ↔ y
  int degree() const { return a != 0 || b != 0 || c != 0 ? 2 : d != 0 || e != 0 ? 1 : 0; }
  Rational operator()(const Rational& x, const Rational& y) const {
    return a * x * x + b * x * y + c * y * y + d * x + e * y + f;
  }
};

// The line through a and b as a degree-1 conic: positive on the left of a → b.
Conic line_conic(const predicates::Point2<Rational>& a, const predicates::Point2<Rational>& b);

}  // namespace anisocert::oracle
