#pragma once
// Exact sums and products of doubles as floating-point expansions (Shewchuk 1997, "Adaptive
// Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", §2): a value is the
// exact sum of a few doubles, non-overlapping and in increasing magnitude, with no zeros. Its
// sign is the sign of its largest component (§2.2: a non-overlapping expansion's largest
// component exceeds the sum of the others in magnitude).
//
// The predicates' exact stage for double inputs (predicates/filtered_sign.hpp): the same
// polynomial code as for double, FilterInterval and Rational, without GMP's allocations and
// gcds. Two things can make an expansion inexact: an overflow, and a product so small that its
// error term underflows. Each operation watches for both, and `exact()` says whether the value
// is still the exact one; when it is not, the caller evaluates in rationals.
//
// Operations, with IEEE 754 round-to-nearest-even doubles:
//   two_sum (Knuth; Shewchuk Theorem 7): a + b = s + e exactly when s and e are finite (sums are
//     exact under gradual underflow; e can be NaN with s finite: s − a overflows when b is near
//     the largest double);
//   two_product (via fma): a · b = p + e exactly when p is finite and |p| >= 2^−968 (below);
//   sum: Fast-Expansion-Sum with zero elimination (Shewchuk Theorem 13), with two_sum at
//     every step (its result is Fast-Two-Sum's wherever that one's precondition holds);
//   scale: Scale-Expansion with zero elimination (Shewchuk Theorem 19);
//   product: the sum of e scaled by each component of f.

#include "numbers/sign.hpp"

#include <boost/container/small_vector.hpp>

#include "numbers/rational.hpp"

#include <cmath>
#include <optional>
#include <span>

namespace anisocert {

class Expansion {
 public:
  Expansion() = default;
  Expansion(double x) : exact_(std::isfinite(x)) {  // NOLINT: a double is an exact value
    if (x != 0) c_.push_back(x);
  }

  friend Expansion operator+(const Expansion& e, const Expansion& f) { return sum(e, f, false); }
  friend Expansion operator-(const Expansion& e, const Expansion& f) { return sum(e, f, true); }
  friend Expansion operator-(const Expansion& e) {
    Expansion r = e;
    for (double& x : r.c_) x = -x;
    return r;
  }
  friend Expansion operator*(const Expansion& e, const Expansion& f) {
    const Components& big = e.c_.size() >= f.c_.size() ? e.c_ : f.c_;
    const Components& small = e.c_.size() >= f.c_.size() ? f.c_ : e.c_;
    Expansion r;
    for (double b : small) r = sum(r, scale(big, b), false);
    r.exact_ = r.exact_ && e.exact_ && f.exact_;
    return r;
  }

  // False once an operation overflowed or a product underflowed: the components are then not the
  // value (a NaN or an infinity among the inputs makes it false too).
  bool exact() const { return exact_; }
  // The value's sign, when exact().
  Sign sign() const {
    if (c_.empty()) return Sign::zero;
    return c_.back() > 0 ? Sign::positive : Sign::negative;
  }
  // A double near the value: the sum of the components from the least (an estimate; Shewchuk
  // §2.8).
  double approx() const {
    double x = 0;
    for (double c : c_) x += c;
    return x;
  }
  // Increasing magnitude, non-overlapping, none zero; their exact sum is the value.
  std::span<const double> components() const { return {c_.data(), c_.size()}; }

 private:
  using Components = boost::container::small_vector<double, 8>;

  static void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a, av = s - bv;
    e = (a - av) + (b - bv);
  }

  // Merges e and ±f by increasing magnitude, then sums them with a running two_sum. An overflow
  // leaves an infinity or a NaN in the running sum, which every later step keeps, or a NaN error
  // term (two_sum above).
  static Expansion sum(const Expansion& ee, const Expansion& ff, bool negate_f) {
    const Components &e = ee.c_, &f = ff.c_;
    Expansion r;
    r.exact_ = ee.exact_ && ff.exact_;
    if (f.empty() || e.empty()) {  // the other, already an expansion
      r.c_ = f.empty() ? e : f;
      if (e.empty() && negate_f)
        for (double& x : r.c_) x = -x;
      return r;
    }
    if (e.size() == 1 && f.size() == 1) {  // the common case, as the loop below would do it
      double s, h;
      two_sum(e[0], negate_f ? -f[0] : f[0], s, h);
      if (h != 0) r.c_.push_back(h);
      if (s != 0) r.c_.push_back(s);
      r.exact_ = r.exact_ && std::isfinite(s) && std::isfinite(h);
      return r;
    }
    Components g;
    g.reserve(e.size() + f.size());
    const double sf = negate_f ? -1.0 : 1.0;
    std::size_t i = 0, j = 0;
    while (i < e.size() || j < f.size()) {
      if (j == f.size() || (i < e.size() && std::fabs(e[i]) <= std::fabs(f[j])))
        g.push_back(e[i++]);
      else
        g.push_back(sf * f[j++]);
    }
    double q = g[0];
    bool finite = true;
    for (std::size_t k = 1; k < g.size(); ++k) {
      double s, h;
      two_sum(q, g[k], s, h);
      if (h != 0) r.c_.push_back(h);
      finite = finite && std::isfinite(h);
      q = s;
    }
    if (q != 0) r.c_.push_back(q);
    r.exact_ = r.exact_ && finite && std::isfinite(q);
    return r;
  }

  // two_product's error term is exact: a = A 2^i, b = B 2^j with |A|, |B| < 2^53, so a · b is a
  // multiple of 2^(i+j) > |a · b| 2^−106, and a · b − p a multiple of the smaller of 2^(i+j) and
  // ulp(p); with |p| >= 2^−968 both are at least 2^−1074 (and the term has at most 53 bits).
  static bool product_exact(double p) { return std::isfinite(p) && std::fabs(p) >= 0x1p-968; }

  // e · b for b != 0 and e's components non-zero, so that every product is non-zero.
  static Expansion scale(const Components& e, double b) {
    Expansion r;
    if (e.empty() || b == 0) return r;
    double q = e[0] * b;
    double h = std::fma(e[0], b, -q);
    r.exact_ = product_exact(q);
    if (h != 0) r.c_.push_back(h);
    for (std::size_t i = 1; i < e.size(); ++i) {
      const double p = e[i] * b, t = std::fma(e[i], b, -p);
      r.exact_ = r.exact_ && product_exact(p);
      double s;
      two_sum(q, t, s, h);
      if (h != 0) r.c_.push_back(h);
      two_sum(p, s, q, h);
      if (h != 0) r.c_.push_back(h);
    }
    if (q != 0) r.c_.push_back(q);
    r.exact_ = r.exact_ && std::isfinite(q);
    return r;
  }

  Components c_;
  bool exact_ = true;
};

// X/D rounded to the nearest double, ties to even (what Boost's conversion of the rational X/D
// gives), from the quotient y of the approximations: the exact remainder x − y·d tells on which
// side of y the quotient lies, and it less or plus half the gap to that neighbour times d, against
// the midpoint (+0 for X = 0); nothing when an expansion is not exact, the quotient is subnormal
// or near overflow, or a few steps do not reach it.
std::optional<double> rounded_quotient(const Expansion& X, const Expansion& D);

// The value of an exact expansion as a rational.
Rational exact_value(const Expansion& e);

}  // namespace anisocert
