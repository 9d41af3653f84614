// Exact parsing and canonical text of rationals (DESIGN.md § Numbers and exactness).
// Expected values are the rationals the strings denote, written by hand.

#include "numbers/excerpt.hpp"
#include "numbers/rational.hpp"

#include <gtest/gtest.h>

using anisocert::NumberSyntaxError;
using anisocert::parse_input_number;
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

TEST(Rational, ErrorQuotesOneShortLine) {
  // A newline in the text would forge a second line of output; a long text, a long message.
  const std::string texts[] = {"1\nanisocert: fake second line", std::string(100000, '7') + "x"};
  for (const std::string& text : texts) {
    try {
      parse_rational(text);
      FAIL() << text.substr(0, 40);
    } catch (const NumberSyntaxError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_LT(m.size(), 120u) << m;
    }
  }
  try {
    parse_rational("1\n2");
  } catch (const NumberSyntaxError& e) {
    EXPECT_EQ(std::string(e.what()), "\"1\\x0a2\" is not an exact number: unexpected character");
  }
}

TEST(Excerpt, KeepsPrintableAsciiEscapesTheRestAndCuts) {
  using anisocert::excerpt;
  EXPECT_EQ(excerpt("Vertices 12"), "Vertices 12");
  EXPECT_EQ(excerpt(std::string_view("a\nb\x00\xce\xb8\x7f", 7)), "a\\x0ab\\x00\\xce\\xb8\\x7f");
  EXPECT_EQ(excerpt(std::string(40, 'x')), std::string(40, 'x'));        // exactly 40: whole
  EXPECT_EQ(excerpt(std::string(41, 'x')), std::string(40, 'x') + "...");
  EXPECT_EQ(excerpt(std::string(38, 'x') + "\n"), std::string(38, 'x') + "...");  // an escape never cut
  EXPECT_EQ(excerpt("abcdef", 3), "abc...");
  EXPECT_EQ(anisocert::quoted_excerpt("\x01\x02z"), "\"\\x01\\x02z\"");
}

TEST(Excerpt, NamesAValueExactlyWhenShortElseByTenDigits) {
  using anisocert::exact_excerpt;
  EXPECT_EQ(exact_excerpt(Rational(-7, 3)), "-7/3");
  EXPECT_EQ(exact_excerpt(parse_rational("0.125")), "0.125");
  EXPECT_EQ(exact_excerpt(parse_rational("1e-330")), "≈1.000000000e-330");
  EXPECT_EQ(exact_excerpt(parse_rational("-123456789012345678901234567890123456789012345")), "≈-1.234567890e+44");
  EXPECT_EQ(exact_excerpt(Rational(1, 3) * parse_rational("1e-50")), "≈3.333333333e-51");
}

TEST(Rational, InputNumbersAreRefusedBeyondTheMagnitudeLimitExactly) {
  using anisocert::Integer;
  using anisocert::max_magnitude_bits;
  using anisocert::within_magnitude_limit;
  const Rational top = Rational(boost::multiprecision::pow(Integer(2), max_magnitude_bits));
  EXPECT_TRUE(within_magnitude_limit(0));
  EXPECT_TRUE(within_magnitude_limit(top));
  EXPECT_TRUE(within_magnitude_limit(-top));
  EXPECT_TRUE(within_magnitude_limit(1 / top));
  EXPECT_FALSE(within_magnitude_limit(top + 1));
  EXPECT_FALSE(within_magnitude_limit(-top - Rational(1, 2)));
  EXPECT_FALSE(within_magnitude_limit(1 / (top + 1)));
  EXPECT_FALSE(within_magnitude_limit(top * 3 / 2));       // within a factor 4: decided exactly
  EXPECT_TRUE(within_magnitude_limit(top * 3 / 4));
  EXPECT_FALSE(within_magnitude_limit(top * top));
  EXPECT_EQ(parse_input_number("1e-330"), parse_rational("1e-330"));   // a little past the doubles: accepted
  EXPECT_EQ(parse_input_number("-1.3e331"), parse_rational("-1.3e331"));
  for (const char* beyond : {"1e-332", "1.4e331", "-1e1000", "1e-100000", "1/" "1" "0000000000000000000000000000000000000000000"
                                                                        "0000000000000000000000000000000000000000000000000000"
                                                                        "0000000000000000000000000000000000000000000000000000"
                                                                        "0000000000000000000000000000000000000000000000000000"
                                                                        "0000000000000000000000000000000000000000000000000000"
                                                                        "0000000000000000000000000000000000000000000000000000"
                                                                        "0000000000000000000000000000000000000000000000000000"}) {
    try {
      parse_input_number(beyond);
      ADD_FAILURE() << beyond;
    } catch (const NumberSyntaxError& e) {
      EXPECT_NE(std::string(e.what()).find("is outside the magnitudes anisocert reads"), std::string::npos) << e.what();
    }
  }
}
