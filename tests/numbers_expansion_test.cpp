// Expansions (numbers/expansion.hpp) against rationals: every exact value is the rational one
// with its components non-overlapping, in increasing magnitude and non-zero (the property the
// sign rests on, Shewchuk §2.2); values that overflowed or underflowed say so; rounded_quotient
// is Boost's correctly rounded conversion of the rational quotient, ties included.
#include "numbers/expansion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using anisocert::Expansion;
using anisocert::Rational;
using anisocert::Sign;

// The exponent of the lowest and of the highest set bit of x ≠ 0.
int lowest_bit(double x) {
  int e;
  double m = std::ldexp(std::frexp(std::fabs(x), &e), 53);  // an integer below 2^53
  int k = e - 53;
  while (std::fmod(m, 2) == 0) m /= 2, ++k;
  return k;
}
int highest_bit(double x) {
  int e;
  std::frexp(std::fabs(x), &e);
  return e - 1;
}

// Non-overlapping (Shewchuk Definition: the highest bit of each component below the lowest of the
// next), increasing, non-zero, finite; and the value is q.
::testing::AssertionResult is_expansion_of(const Expansion& e, const Rational& q) {
  const auto c = e.components();
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] == 0 || !std::isfinite(c[i])) return ::testing::AssertionFailure() << "component " << i << " is " << c[i];
    if (i > 0 && highest_bit(c[i - 1]) >= lowest_bit(c[i])) return ::testing::AssertionFailure() << "components " << i - 1 << " and " << i << " overlap";
  }
  if (anisocert::exact_value(e) != q) return ::testing::AssertionFailure() << "value differs from the rational";
  if (e.sign() != anisocert::sign_of(q)) return ::testing::AssertionFailure() << "sign differs";
  return ::testing::AssertionSuccess();
}

struct Random {
  std::mt19937_64 rng;
  explicit Random(unsigned seed) : rng(seed) {}
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  // A double with about 53 random bits, or a few, at exponent e; sometimes 0.
  double number(int e) {
    if (integer(0, 15) == 0) return 0;
    const double m = integer(0, 1) ? std::uniform_real_distribution<double>(-1, 1)(rng) : integer(-8, 8) / 8.0;
    return std::ldexp(m, e);
  }
};

// Random sums, differences and products of random depth, evaluated both ways.
void evaluate(Random& r, int depth, int lo, int hi, Expansion& e, Rational& q) {
  if (depth == 0 || r.integer(0, 3) == 0) {
    const double x = r.number(r.integer(lo, hi));
    e = Expansion(x), q = Rational(x);
    return;
  }
  Expansion e1, e2;
  Rational q1, q2;
  evaluate(r, depth - 1, lo, hi, e1, q1);
  evaluate(r, depth - 1, lo, hi, e2, q2);
  switch (r.integer(0, 3)) {
    case 0: e = e1 + e2, q = q1 + q2; break;
    case 1: e = e1 - e2, q = q1 - q2; break;
    case 2: e = -e1, q = -q1; break;
    default: e = e1 * e2, q = q1 * q2;
  }
}

}  // namespace

TEST(Expansion, ExactWithinTheRangeOfPolynomialsOfDegreeEight) {
  // Inputs within [2^-64, 2^64] and depth 3 (degree at most 8): never an overflow or an underflow.
  Random r(1);
  for (int t = 0; t < 20000; ++t) {
    Expansion e;
    Rational q;
    evaluate(r, 3, -64, 64, e, q);
    ASSERT_TRUE(e.exact()) << "case " << t;
    ASSERT_TRUE(is_expansion_of(e, q)) << "case " << t;
  }
}

TEST(Expansion, SaysWhenItOverflowedOrUnderflowed) {
  // Across the doubles' whole range: an exact() value is the rational one; cases of both kinds occur.
  Random r(2);
  int exact = 0, inexact = 0;
  for (int t = 0; t < 20000; ++t) {
    Expansion e;
    Rational q;
    evaluate(r, 4, -1074, 1023, e, q);
    if (!e.exact()) {
      ++inexact;
      continue;
    }
    ++exact;
    ASSERT_TRUE(is_expansion_of(e, q)) << "case " << t;
  }
  EXPECT_GT(exact, 2000);
  EXPECT_GT(inexact, 2000);
  // Hand-made: a product whose error term would fall below the subnormals, and an overflow.
  EXPECT_FALSE((Expansion(0x1.0000000000001p-600) * Expansion(0x1.0000000000001p-500)).exact());
  EXPECT_FALSE((Expansion(0x1p1000) * Expansion(0x1p100)).exact());
  EXPECT_FALSE((Expansion(0x1.fffffffffffffp1023) + Expansion(0x1.fffffffffffffp1023)).exact());
  EXPECT_FALSE(Expansion(NAN).exact());
  // Review finding: −3·2^970 + the largest double is finite, but two_sum's error term overflows
  // (s − a rounds to ∞): a NaN component.
  EXPECT_FALSE((Expansion(-0x3p970) + Expansion(0x1.fffffffffffffp1023)).exact());
  EXPECT_FALSE((Expansion(-0x3p970) + Expansion(0x1p-10) + Expansion(0x1.fffffffffffffp1023)).exact());
  EXPECT_TRUE((Expansion(0x1p-600) * Expansion(0) + Expansion(1)).exact());
}

TEST(Expansion, ExactZerosOfDegenerateConfigurations) {
  // (1 + 2^-52)² − 1 − 2^-51 = 2^-104: the doubles lose it; the expansion keeps it.
  const Expansion x = Expansion(1) + Expansion(0x1p-52);
  const Expansion v = x * x - Expansion(1) - Expansion(0x1p-51);
  EXPECT_TRUE(is_expansion_of(v, Rational(anisocert::Integer(1), anisocert::Integer(1) << 104)));
  EXPECT_EQ((v - Expansion(0x1p-104)).sign(), Sign::zero);
  // 0.1 · 3 − 0.3 is not 0 in the rationals the doubles denote.
  EXPECT_TRUE(is_expansion_of(Expansion(0.1) * Expansion(3) - Expansion(0.3), Rational(0.1) * 3 - Rational(0.3)));
}

TEST(RoundedQuotient, IsBoostsCorrectlyRoundedConversion) {
  Random r(3);
  int answered = 0;
  for (int t = 0; t < 20000; ++t) {
    Expansion x, d;
    Rational qx, qd;
    evaluate(r, 3, -40, 40, x, qx);
    evaluate(r, 3, -40, 40, d, qd);
    if (qd == 0) continue;
    const auto y = anisocert::rounded_quotient(x, d);
    const double expected = Rational(qx / qd).convert_to<double>();
    if (!y) {
      // Only a subnormal or huge quotient may be left to the rationals.
      ASSERT_TRUE(std::fabs(expected) < 0x1p-1020 || std::fabs(expected) > 0x1p1021) << "case " << t;
      continue;
    }
    ++answered;
    ASSERT_EQ(*y, expected) << "case " << t;
  }
  EXPECT_GT(answered, 15000);
}

TEST(RoundedQuotient, TiesGoToTheEvenNeighbour) {
  using anisocert::rounded_quotient;
  // 1 + 2^-53 lies half-way between 1 and 1 + 2^-52: 1 is even.
  EXPECT_EQ(rounded_quotient(Expansion(1) + Expansion(0x1p-53), Expansion(1)), 1.0);
  // 1 + 3·2^-53 lies half-way between 1 + 2^-52 (odd) and 1 + 2^-51 (even).
  EXPECT_EQ(rounded_quotient(Expansion(1) + Expansion(3 * 0x1p-53), Expansion(1)), 1 + 0x1p-51);
  // The same ties, negative, and scaled through the divisor: (6 + 3·2^-52) / −6 = −(1 + 2^-53).
  EXPECT_EQ(rounded_quotient(Expansion(6) + Expansion(3 * 0x1p-52), Expansion(-6)), -1.0);
  // Below a power of two the gap halves: 1 − 2^-54 lies half-way between 1 − 2^-53 (odd) and 1
  // (even); 1 − 3·2^-54 between 1 − 2^-52 (even) and 1 − 2^-53.
  EXPECT_EQ(rounded_quotient(Expansion(1) - Expansion(0x1p-54), Expansion(1)), 1.0);
  EXPECT_EQ(rounded_quotient(Expansion(1) - Expansion(3 * 0x1p-54), Expansion(1)), 1 - 0x1p-52);
  EXPECT_EQ(rounded_quotient(Expansion(1), Expansion(3)), 1.0 / 3);
  EXPECT_EQ(rounded_quotient(Expansion(0), Expansion(3)), 0.0);
}
