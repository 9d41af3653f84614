// Exact parsing and canonical text of rationals (DESIGN.md § Numbers and exactness).
// Expected values are the rationals the strings denote, written by hand.

#include "numbers/rational.hpp"

#include <gtest/gtest.h>

using anisocert::NumberSyntaxError;
using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::to_exact_string;

TEST(Rational, ParsesIntegersDecimalsFractionsExactly) {
  EXPECT_EQ(parse_rational("12"), Rational(12));
  EXPECT_EQ(parse_rational("-7"), Rational(-7));
  EXPECT_EQ(parse_rational("+3"), Rational(3));
  EXPECT_EQ(parse_rational("12.5"), Rational(25, 2));
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));  // not the double 0.1
  EXPECT_EQ(parse_rational(".5"), Rational(1, 2));
  EXPECT_EQ(parse_rational("3."), Rational(3));
  EXPECT_EQ(parse_rational("-0.125"), Rational(-1, 8));
  EXPECT_EQ(parse_rational("010"), Rational(10));  // decimal, never octal
  EXPECT_EQ(parse_rational("1.25e-3"), Rational(1, 800));
  EXPECT_EQ(parse_rational("4E2"), Rational(400));
  EXPECT_EQ(parse_rational("-7/3"), Rational(-7, 3));
  EXPECT_EQ(parse_rational("6/-4"), Rational(-3, 2));
  EXPECT_EQ(parse_rational("0/5"), Rational(0));
  EXPECT_EQ(parse_rational("20.70481105463542966924025109346286037089"),
            Rational(anisocert::Integer{"2070481105463542966924025109346286037089"},
                     boost::multiprecision::pow(anisocert::Integer{10}, 38)));
}

TEST(Rational, RejectsWhatIsNotAnExactNumber) {
  for (const char* bad : {"", " 1", "1 ", "abc", "1..2", "1.2.3", "--1", "1/0", "1/", "/2", "1.5/2", "inf", "nan",
                          "0x10", "08x", "1e", "1e+", "e5", ".", "-", "1e1000000", "1e99999999999"}) {
    EXPECT_THROW(parse_rational(bad), NumberSyntaxError) << '"' << bad << '"';
  }
}

TEST(Rational, ErrorNamesTheText) {
  try {
    parse_rational("12x");
    FAIL();
  } catch (const NumberSyntaxError& e) {
    EXPECT_NE(std::string(e.what()).find("\"12x\""), std::string::npos);
  }
}

TEST(Rational, ExactStringIsCanonicalAndRoundTrips) {
  EXPECT_EQ(to_exact_string(Rational(25, 2)), "12.5");
  EXPECT_EQ(to_exact_string(Rational(-3)), "-3");
  EXPECT_EQ(to_exact_string(Rational(1, 1000)), "0.001");
  EXPECT_EQ(to_exact_string(Rational(-1, 8)), "-0.125");
  EXPECT_EQ(to_exact_string(Rational(1, 3)), "1/3");
  EXPECT_EQ(to_exact_string(Rational(-10, 6)), "-5/3");
  EXPECT_EQ(to_exact_string(Rational(0)), "0");
  for (const char* s : {"12.5", "-0.0001", "7/3", "123456789.987654321", "-1/7"})
    EXPECT_EQ(parse_rational(to_exact_string(parse_rational(s))), parse_rational(s)) << s;
}
