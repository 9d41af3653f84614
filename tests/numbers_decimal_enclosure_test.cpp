// Decimal text of enclosures: outward directed rounding and the certified prefix.
// Expected strings are written by hand from the rationals' decimal expansions.

#include "numbers/decimal_enclosure.hpp"

#include <gtest/gtest.h>

using anisocert::Rational;
using namespace anisocert;

TEST(DecimalEnclosure, RoundsOutward) {
  DecimalEnclosure third = to_decimal(Interval(Rational(1, 3), 128), 10);
  EXPECT_EQ(third.lo, "0.3333333333");
  EXPECT_EQ(third.hi, "0.3333333334");
  DecimalEnclosure minus = to_decimal(Interval(Rational(-2, 3), 128), 5);
  EXPECT_EQ(minus.lo, "-0.66667");
  EXPECT_EQ(minus.hi, "-0.66666");
  DecimalEnclosure big = to_decimal(Interval(Rational(123456789), 128), 4);
  EXPECT_EQ(big.lo, "123400000");
  EXPECT_EQ(big.hi, "123500000");
  DecimalEnclosure small = to_decimal(Interval(Rational(1, 7000), 128), 3);
  EXPECT_EQ(small.lo, "0.000142");
  EXPECT_EQ(small.hi, "0.000143");
  DecimalEnclosure exact = to_decimal(Interval(Rational(5, 4), 128), 10);
  EXPECT_EQ(exact.lo, "1.25");
  EXPECT_EQ(exact.hi, "1.25");
  DecimalEnclosure zero = to_decimal(Interval(Rational(0), 128), 10);
  EXPECT_EQ(zero.lo, "0");
  EXPECT_EQ(zero.hi, "0");
}

TEST(DecimalEnclosure, DecimalEndpointsStillContainTheValue) {
  for (int digits : {1, 2, 3, 10, 40}) {
    Interval x(Rational(22, 7), 200);
    DecimalEnclosure d = to_decimal(x, digits);
    EXPECT_LE(anisocert::parse_rational(d.lo), Rational(22, 7)) << digits;
    EXPECT_GE(anisocert::parse_rational(d.hi), Rational(22, 7)) << digits;
  }
}

TEST(DecimalEnclosure, CertifiedDigitsAreACommonTruncation) {
  EXPECT_EQ(certified_digits({"1.12783848556", "1.12783848557"}), "1.1278384855…");
  EXPECT_EQ(certified_digits({"1.2999", "1.3001"}), "1…");
  EXPECT_EQ(certified_digits({"9.99", "10.01"}), "?");
  EXPECT_EQ(certified_digits({"-0.1", "0.1"}), "?");
  EXPECT_EQ(certified_digits({"1.25", "1.25"}), "1.25");
  EXPECT_EQ(certified_digits({"123.4", "125.1"}), "?");
  // Whole numbers of different lengths share a prefix but not a magnitude (review finding).
  EXPECT_EQ(certified_digits({"1", "12"}), "?");
  EXPECT_EQ(certified_digits({"10", "100"}), "?");
  EXPECT_EQ(certified_digits({"10", "19"}), "?");
  EXPECT_EQ(certified_digits({"12.5", "12.7"}), "12…");
  EXPECT_EQ(common_significant_digits({"1.5", "15"}), 0);
  EXPECT_EQ(common_significant_digits({"10", "100"}), 0);
  EXPECT_EQ(common_significant_digits({"0.0031415", "0.0031416"}), 4);
  EXPECT_EQ(common_significant_digits({"78.98984", "78.98985"}), 6);
  // The sign is no digit: a negative enclosure has as many as its mirror image.
  EXPECT_EQ(common_significant_digits({"-78.98985", "-78.98984"}), 6);
  EXPECT_EQ(common_significant_digits({"-0.0031416", "-0.0031415"}), 4);
}
