#pragma once
// Certified real intervals for theory/ (DESIGN.md § Numbers: "arbitrary-precision intervals
// (MPFR/MPFI) for certified refinement and for theory/").
//
// An Interval is a closed interval [lo, hi] with MPFR endpoints. Every operation is MPFI's,
// which rounds the endpoints outward, so the result contains the exact image of every point
// of the operands (the inclusion property). All certified values of theory/ are built from
// exact rationals and these operations only; that is the whole correctness argument.
//
// A result's precision is the larger of its operands' precisions.

#include "numbers/rational.hpp"

#include <mpfi.h>

#include <optional>

namespace anisocert {

class Interval {
 public:
  // The smallest interval with prec-bit endpoints that contains q.
  Interval(const Rational& q, mpfr_prec_t prec);
  // [lo, hi] for MPFR numbers lo <= hi (rounded outward if they have more than prec bits).
  Interval(mpfr_srcptr lo, mpfr_srcptr hi, mpfr_prec_t prec);
  // The point d (exact when prec >= 53).
  Interval(double d, mpfr_prec_t prec);
  // [lo, hi] for doubles lo <= hi (exact when prec >= 53).
  Interval(double lo, double hi, mpfr_prec_t prec);
  static Interval pi(mpfr_prec_t prec);

  Interval(const Interval& other);
  Interval(Interval&& other) noexcept;
  Interval& operator=(Interval other) noexcept;
  ~Interval();

  mpfr_prec_t precision() const { return mpfi_get_prec(v_); }
  mpfr_srcptr lower() const { return &v_->left; }
  mpfr_srcptr upper() const { return &v_->right; }

  bool certainly_positive() const;  // lo > 0
  bool certainly_negative() const;  // hi < 0
  bool contains(const Rational& q) const;
  // [lo, hi] ⊂ [a, b] for rationals a <= b.
  bool inside(const Rational& a, const Rational& b) const;
  bool has_zero() const { return mpfi_has_zero(v_) > 0 || mpfi_nan_p(v_); }  // NaN: 0 not excluded
  // [lo, hi] ⊂ (outer.lo, outer.hi).
  bool strictly_inside(const Interval& outer) const;
  // A point of the interval near its middle, as a point interval (for centred forms and
  // Krawczyk's operator, where any point of the interval will do).
  Interval midpoint() const;
  // The same interval at a higher precision (exact), or rounded outward to a lower one.
  Interval at_precision(mpfr_prec_t prec) const;
  // The endpoints rounded outward to doubles.
  double lower_double() const { return mpfr_get_d(lower(), MPFR_RNDD); }
  double upper_double() const { return mpfr_get_d(upper(), MPFR_RNDU); }

  friend Interval operator+(const Interval& a, const Interval& b);
  friend Interval operator-(const Interval& a, const Interval& b);
  friend Interval operator*(const Interval& a, const Interval& b);
  friend Interval operator/(const Interval& a, const Interval& b);
  friend Interval operator-(const Interval& a);
  friend Interval operator+(const Interval& a, long b);
  friend Interval operator-(const Interval& a, long b);
  friend Interval operator+(long a, const Interval& b);
  friend Interval operator-(long a, const Interval& b);
  friend Interval operator*(long a, const Interval& b);
  friend Interval operator/(const Interval& a, long b);
  friend Interval operator/(long a, const Interval& b);

  friend Interval sqr(const Interval& a);
  // The functions below require their argument inside their domain (sqrt: [0, inf),
  // asin/acos: [-1, 1]) and throw std::domain_error otherwise: theory/ never encloses a
  // value that is not defined.
  friend Interval sqrt(const Interval& a);
  friend Interval sin(const Interval& a);
  friend Interval asin(const Interval& a);
  friend Interval acos(const Interval& a);
  friend Interval atan(const Interval& a);
  friend std::optional<Interval> intersection(const Interval& a, const Interval& b);

 private:
  explicit Interval(mpfr_prec_t prec);
  mpfi_t v_;
};

// a ∩ b, or nothing when they are disjoint.
std::optional<Interval> intersection(const Interval& a, const Interval& b);
// a < b for every point of a and of b (hi(a) < lo(b)).
bool certainly_less(const Interval& a, const Interval& b);
// The degree measure of an angle given in radians, and the reverse.
Interval degrees(const Interval& radians);
Interval radians(const Interval& degrees);

}  // namespace anisocert
