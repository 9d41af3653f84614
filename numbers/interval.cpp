#include "numbers/interval.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace anisocert {
namespace {

mpfr_prec_t joint(const Interval& a, const Interval& b) { return std::max(a.precision(), b.precision()); }

}  // namespace

Interval::Interval(mpfr_prec_t prec) { mpfi_init2(v_, prec); }

Interval::Interval(const Rational& q, mpfr_prec_t prec) : Interval(prec) {
  mpfi_set_q(v_, q.backend().data());
}

Interval::Interval(mpfr_srcptr lo, mpfr_srcptr hi, mpfr_prec_t prec) : Interval(prec) {
  if (mpfr_cmp(lo, hi) > 0) throw std::logic_error("Interval: lo > hi");
  mpfi_interv_fr(v_, lo, hi);
}

Interval::Interval(double d, mpfr_prec_t prec) : Interval(prec) { mpfi_set_d(v_, d); }

Interval::Interval(double lo, double hi, mpfr_prec_t prec) : Interval(prec) {
  if (!(lo <= hi)) throw std::logic_error("Interval: lo > hi");
  mpfi_interv_d(v_, lo, hi);
}

Interval Interval::pi(mpfr_prec_t prec) {
  Interval r(prec);
  mpfi_const_pi(r.v_);
  return r;
}

Interval::Interval(const Interval& other) : Interval(other.precision()) { mpfi_set(v_, other.v_); }

Interval::Interval(Interval&& other) noexcept : Interval(other.precision()) { mpfi_swap(v_, other.v_); }

Interval& Interval::operator=(Interval other) noexcept {
  mpfi_swap(v_, other.v_);
  return *this;
}

Interval::~Interval() { mpfi_clear(v_); }

bool Interval::certainly_positive() const { return mpfr_sgn(lower()) > 0; }
bool Interval::certainly_negative() const { return mpfr_sgn(upper()) < 0; }

bool Interval::contains(const Rational& q) const {
  return mpfr_cmp_q(lower(), q.backend().data()) <= 0 && mpfr_cmp_q(upper(), q.backend().data()) >= 0;
}

bool Interval::inside(const Rational& a, const Rational& b) const {
  return mpfr_cmp_q(lower(), a.backend().data()) >= 0 && mpfr_cmp_q(upper(), b.backend().data()) <= 0;
}

bool Interval::strictly_inside(const Interval& outer) const {
  return mpfr_cmp(lower(), outer.lower()) > 0 && mpfr_cmp(upper(), outer.upper()) < 0;
}

Interval Interval::midpoint() const {
  mpfr_t m;
  mpfr_init2(m, precision());
  mpfi_mid(m, v_);  // rounded to nearest: a point of [lo, hi], which is all a midpoint must be
  Interval r(m, m, precision());
  mpfr_clear(m);
  return r;
}

Interval Interval::at_precision(mpfr_prec_t prec) const {
  Interval r(prec);
  mpfi_set(r.v_, v_);
  return r;
}

std::optional<Interval> intersection(const Interval& a, const Interval& b) {
  if (mpfr_cmp(a.upper(), b.lower()) < 0 || mpfr_cmp(b.upper(), a.lower()) < 0) return std::nullopt;
  Interval r = a.at_precision(std::max(a.precision(), b.precision()));
  mpfi_intersect(r.v_, a.v_, b.v_);
  return r;
}

#define ANISOCERT_BINARY(op, fn)                                 \
  Interval operator op(const Interval& a, const Interval& b) {   \
    Interval r(joint(a, b));                                     \
    fn(r.v_, a.v_, b.v_);                                        \
    return r;                                                    \
  }
ANISOCERT_BINARY(+, mpfi_add)
ANISOCERT_BINARY(-, mpfi_sub)
ANISOCERT_BINARY(*, mpfi_mul)
#undef ANISOCERT_BINARY

Interval operator-(const Interval& a) {
  Interval r(a.precision());
  mpfi_neg(r.v_, a.v_);
  return r;
}

Interval operator/(const Interval& a, const Interval& b) {
  if (mpfi_has_zero(b.v_)) throw std::domain_error("interval division by an interval containing 0");
  Interval r(joint(a, b));
  mpfi_div(r.v_, a.v_, b.v_);
  return r;
}

Interval operator+(const Interval& a, long b) {
  Interval r(a.precision());
  mpfi_add_si(r.v_, a.v_, b);
  return r;
}
Interval operator-(const Interval& a, long b) {
  Interval r(a.precision());
  mpfi_sub_si(r.v_, a.v_, b);
  return r;
}
Interval operator+(long a, const Interval& b) { return b + a; }
Interval operator-(long a, const Interval& b) {
  Interval r(b.precision());
  mpfi_si_sub(r.v_, a, b.v_);
  return r;
}
Interval operator*(long a, const Interval& b) {
  Interval r(b.precision());
  mpfi_mul_si(r.v_, b.v_, a);
  return r;
}
Interval operator/(const Interval& a, long b) {
  if (b == 0) throw std::domain_error("interval division by 0");
  Interval r(a.precision());
  mpfi_div_si(r.v_, a.v_, b);
  return r;
}
Interval operator/(long a, const Interval& b) {
  if (mpfi_has_zero(b.v_)) throw std::domain_error("interval division by an interval containing 0");
  Interval r(b.precision());
  mpfi_si_div(r.v_, a, b.v_);
  return r;
}

Interval sqr(const Interval& a) {
  Interval r(a.precision());
  mpfi_sqr(r.v_, a.v_);
  return r;
}

Interval sqrt(const Interval& a) {
  if (mpfr_sgn(a.lower()) < 0) throw std::domain_error("sqrt of an interval reaching below 0");
  Interval r(a.precision());
  mpfi_sqrt(r.v_, a.v_);
  return r;
}

Interval sin(const Interval& a) {
  Interval r(a.precision());
  mpfi_sin(r.v_, a.v_);
  return r;
}

static void require_unit_range(const Interval& a, const char* what) {
  if (mpfr_cmp_si(a.lower(), -1) < 0 || mpfr_cmp_si(a.upper(), 1) > 0)
    throw std::domain_error(std::string(what) + " of an interval reaching outside [-1, 1]");
}

Interval asin(const Interval& a) {
  require_unit_range(a, "asin");
  Interval r(a.precision());
  mpfi_asin(r.v_, a.v_);
  return r;
}

Interval acos(const Interval& a) {
  require_unit_range(a, "acos");
  Interval r(a.precision());
  mpfi_acos(r.v_, a.v_);
  return r;
}

Interval atan(const Interval& a) {
  Interval r(a.precision());
  mpfi_atan(r.v_, a.v_);
  return r;
}

bool certainly_less(const Interval& a, const Interval& b) { return mpfr_cmp(a.upper(), b.lower()) < 0; }

Interval degrees(const Interval& radians) { return 180 * radians / Interval::pi(radians.precision()); }
Interval radians(const Interval& degrees) { return degrees * Interval::pi(degrees.precision()) / 180; }

}  // namespace anisocert
