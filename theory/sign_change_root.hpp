#pragma once
// Certified enclosure of a root by bisection on sign changes of an interval extension.

#include "numbers/interval.hpp"

#include <functional>

namespace anisocert::theory {

// f is an interval extension of a continuous real function (f(X) contains f(x) for x in X).
// Given rationals a < b with f certainly negative at a and certainly positive at b, returns
// [lo, hi] ⊂ [a, b] with f(lo) certainly < 0 and f(hi) certainly > 0, so by the intermediate
// value theorem a root lies in (lo, hi). The caller argues uniqueness (e.g. monotonicity).
// Bisection stops when lo and hi are adjacent prec-bit numbers or when f cannot decide the sign
// at a midpoint; the result is correct either way, only its width differs.
// Throws std::logic_error when the endpoint signs are not as required.
Interval enclose_sign_change(const std::function<Interval(const Interval&)>& f, const Rational& a,
                             const Rational& b, mpfr_prec_t prec);

// True when f is certainly negative at lo and certainly positive at hi: the check a reader
// can repeat on a printed enclosure (LS Theorem 11's "verified, not trusted").
bool brackets_sign_change(const std::function<Interval(const Interval&)>& f, const Rational& lo,
                          const Rational& hi, mpfr_prec_t prec);

}  // namespace anisocert::theory
