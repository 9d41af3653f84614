// The interval layer of theory/: inclusion of exact rationals, domain errors instead of
// undefined enclosures, and the order predicates.

#include "numbers/interval.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using anisocert::Rational;
using anisocert::Interval;

TEST(Interval, EnclosesRationalsThatBinaryCannotRepresent) {
  Interval third(Rational(1, 3), 64);
  EXPECT_TRUE(third.contains(Rational(1, 3)));
  EXPECT_FALSE(third.contains(Rational(1, 3) + Rational(1, 1000000)));
  EXPECT_TRUE(third.certainly_positive());
  EXPECT_FALSE(third.certainly_negative());
}

TEST(Interval, ArithmeticContainsTheExactResult) {
  // (1/3 + 1/7) * 3/11 − 2/5 = −104/385 (by hand: 10/21 * 3/11 = 10/77; 10/77 − 2/5 = −104/385).
  const mpfr_prec_t p = 80;
  Interval r = (Interval(Rational(1, 3), p) + Interval(Rational(1, 7), p)) * Interval(Rational(3, 11), p) -
               Interval(Rational(2, 5), p);
  EXPECT_TRUE(r.contains(Rational(-104, 385)));
  EXPECT_TRUE(r.certainly_negative());
  Interval s = sqr(sqrt(Interval(Rational(2), p)));
  EXPECT_TRUE(s.contains(Rational(2)));
}

TEST(Interval, RefusesValuesOutsideTheDomain) {
  const mpfr_prec_t p = 64;
  EXPECT_THROW(sqrt(Interval(Rational(-1, 1000), p)), std::domain_error);
  EXPECT_THROW(asin(Interval(Rational(1001, 1000), p)), std::domain_error);
  EXPECT_THROW(acos(Interval(Rational(-1001, 1000), p)), std::domain_error);
  EXPECT_THROW(Interval(Rational(1), p) / Interval(Rational(0), p), std::domain_error);
  EXPECT_NO_THROW(asin(Interval(Rational(1), p)));
}

TEST(Interval, CertainlyLessSeparatesOnlyDisjointIntervals) {
  const mpfr_prec_t p = 64;
  Interval a(Rational(1, 3), p), b(Rational(1, 2), p);
  EXPECT_TRUE(certainly_less(a, b));
  EXPECT_FALSE(certainly_less(b, a));
  EXPECT_FALSE(certainly_less(a, a));  // overlapping: undecided, never "less"
}

TEST(Interval, DegreesOfPiOverSixIsThirty) {
  // asin(1/2) = π/6 = 30°: a closed form.
  Interval thirty = degrees(asin(Interval(Rational(1, 2), 128)));
  EXPECT_TRUE(thirty.contains(Rational(30)));
  EXPECT_TRUE(thirty.inside(Rational(29999999, 1000000), Rational(30000001, 1000000)));
}

// [lo, hi] ⊂ (outer.lo, outer.hi) needs both ends strictly inside (the 2026-12-02 campaign's
// mutant checking the upper end only survived).
TEST(Interval, StrictlyInsideNeedsBothEnds) {
  const Interval outer(0.5, 2.0, 64);
  EXPECT_TRUE(Interval(1.0, 1.5, 64).strictly_inside(outer));
  EXPECT_FALSE(Interval(0.25, 1.5, 64).strictly_inside(outer));  // the lower end outside
  EXPECT_FALSE(Interval(0.5, 1.5, 64).strictly_inside(outer));   // on the lower end
  EXPECT_FALSE(Interval(1.0, 2.0, 64).strictly_inside(outer));   // on the upper end
}
