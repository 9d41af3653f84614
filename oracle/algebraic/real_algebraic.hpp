#pragma once
// Real algebraic numbers: a real root of a square-free polynomial with rational coefficients,
// given by an isolating interval with rational ends. Every question about them is decided
// exactly: signs of polynomials (zero included, by a gcd), comparisons, equality; decimals are
// correctly rounded.

#include "oracle/algebraic/polynomial.hpp"

#include <optional>
#include <string>
#include <vector>

namespace anisocert::oracle {

class RealAlgebraic {
 public:
  // The root of the square-free p in [lo, hi], where either lo == hi and p(lo) = 0, or lo < hi,
  // p(lo)·p(hi) < 0 and p has no other root in [lo, hi]. The sign conditions are checked (throws
  // std::invalid_argument); square-freeness and uniqueness are the caller's guarantee (every
  // caller isolates with Sturm sequences of a square-free part).
  RealAlgebraic(Polynomial squarefree, Rational lo, Rational hi);
  static RealAlgebraic rational(const Rational& q);

  const Polynomial& polynomial() const { return p_; }
  const Rational& lo() const { return lo_; }
  const Rational& hi() const { return hi_; }
  bool is_exact() const { return lo_ == hi_; }

  // The value when it is rational, else nothing: decided exactly, whatever the interval (a
  // rational root a/b in lowest terms of p = P/L, P integral, has b | lc(P)).
  std::optional<Rational> as_rational() const;

  // Halves the isolating interval (or finds the root exactly at the midpoint).
  void refine() const;
  void refine_below(const Rational& width) const;

  // sign(q(α)), exact: the interval value of q on up to `fast_refinements` refinements of the
  // isolating interval first, then the exact zero test (a gcd) and refinement.
  Sign sign_of(const Polynomial& q) const;
  static constexpr int fast_refinements = 16;

  // The value correctly rounded to `digits` significant decimal digits ("0" for zero),
  // positional or, beyond 10^±30, with an exponent "1.25e-40".
  std::string decimal(int digits) const;

 private:
  Polynomial p_;
  mutable Rational lo_, hi_;
};

// sign(a − b), exact.
Sign compare(const RealAlgebraic& a, const RealAlgebraic& b);

// The real roots of p (non-zero), each once, increasing, isolated for squarefree_part(p).
std::vector<RealAlgebraic> real_roots(const Polynomial& p);

// The Sturm sequence p, p', −rem(p, p'), … of a square-free p, and with it the number of
// distinct roots of p in (a, b] (Sturm's theorem).
std::vector<Polynomial> sturm_sequence(const Polynomial& squarefree);
int count_roots(const std::vector<Polynomial>& sturm, const Rational& a, const Rational& b);

// The multiplicity of α as a root of p (0 if it is not a root).
int multiplicity(const RealAlgebraic& alpha, const Polynomial& p);

}  // namespace anisocert::oracle
