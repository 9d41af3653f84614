// LS Theorem 11 against closed forms and against the digits printed in the paper.

#include "numbers/decimal_enclosure.hpp"
#include "theory/ls_theorem11.hpp"
#include "theory/sign_change_root.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

using anisocert::parse_rational;
using anisocert::Rational;
using namespace anisocert::theory;
using namespace anisocert;

namespace {
const mpfr_prec_t prec = 256;

Rational ten_to_minus(int k) { return Rational(1, boost::multiprecision::pow(anisocert::Integer{10}, k)); }

bool overlap(const Interval& a, const Interval& b) { return !certainly_less(a, b) && !certainly_less(b, a); }

// Both enclose the same number to at least `digits` significant digits.
void expect_same_value(const Interval& a, const Interval& b, int digits) {
  EXPECT_TRUE(overlap(a, b));
  EXPECT_GE(common_significant_digits(to_decimal(a, digits + 5)), digits);
  EXPECT_GE(common_significant_digits(to_decimal(b, digits + 5)), digits);
}

Interval golden_ratio() { return (1 + sqrt(Interval(Rational(5), prec))) / 2; }
}  // namespace

TEST(LS_T11, GammaAtZeroIsFourthRootOfGoldenRatio) {
  // θ = 0: γ⁸ − γ⁴ − 1 = 0, so γ⁴ = φ = (1 + √5)/2 (closed form).
  Interval gamma = ls_t11_gamma(Rational(0), prec);
  expect_same_value(gamma, sqrt(sqrt(golden_ratio())), 60);
  // Second engine: Python's decimal module at 60 digits, (((1+5**.5)/2)**.5)**.5.
  Rational python = parse_rational("1.12783848556168226026483548317704245843646833542365576729005");
  EXPECT_TRUE(gamma.inside(python - ten_to_minus(57), python + ten_to_minus(57)));
}

TEST(LS_T11, AgreesWithTheDigitsPrintedInThePaper) {
  // LS §10: "If θbound = 0°, γ ≐ 1.1278 ... If θbound = 10°, γ ≐ 1.0629", "about 20.7°",
  // "This angle is less than 79°".
  EXPECT_TRUE(ls_t11_gamma(Rational(0), prec).inside(parse_rational("1.12775"), parse_rational("1.12785")));
  EXPECT_TRUE(ls_t11_gamma(Rational(10), prec).inside(parse_rational("1.06285"), parse_rational("1.06295")));
  EXPECT_TRUE(ls_t11_theta_max_deg(prec).inside(parse_rational("20.65"), parse_rational("20.75")));
  Interval angle0 = ls_t11_segment_angle_deg(ls_t11_gamma(Rational(0), prec));
  EXPECT_TRUE(angle0.inside(Rational(78), Rational(79)));
}

TEST(LS_T11, ThetaMaxIsArctanOfOneOverSqrt7) {
  // sin²θ = 1/8 ⇔ tan θ = (1/√8)/√(7/8) = 1/√7 (closed form, a different function of MPFI).
  Interval by_atan = degrees(atan(1 / sqrt(Interval(Rational(7), prec))));
  expect_same_value(ls_t11_theta_max_deg(prec), by_atan, 60);
}

TEST(LS_T11, SegmentAngleAtZeroIsArccosOfOneMinusHalfPhi) {
  // cos(2x) = 1 − 2 sin²x with sin x = γ²/2 and γ⁴ = φ gives 2·arcsin(γ²/2) = arccos(1 − φ/2).
  Interval closed = degrees(acos(1 - golden_ratio() / 2));
  expect_same_value(ls_t11_segment_angle_deg(ls_t11_gamma(Rational(0), prec)), closed, 60);
}

TEST(LS_T11, DistanceFactorAtZeroFromGoldenRatio) {
  // γ² = √φ: 1/((γ⁵+γ³)√(γ²+1)) = 1/(γ³ (γ²+1)^(3/2)) with γ³ = φ^(3/4).
  Interval g2 = sqrt(golden_ratio());
  Interval closed = 1 / (g2 * sqrt(g2) * (g2 + 1) * sqrt(g2 + 1));
  expect_same_value(ls_t11_distance_factor(ls_t11_gamma(Rational(0), prec)), closed, 60);
}

TEST(LS_T11, AdmissibilityIsDecidedExactlyEvenAtHundredsOfDigits) {
  EXPECT_TRUE(ls_t11_theta_admissible(Rational(0)));
  EXPECT_FALSE(ls_t11_theta_admissible(-ten_to_minus(30)));
  EXPECT_TRUE(ls_t11_theta_admissible(parse_rational("20.7")));
  EXPECT_FALSE(ls_t11_theta_admissible(parse_rational("20.705")));
  EXPECT_FALSE(ls_t11_theta_admissible(Rational(90)));
  // θ_max rounded down / up to 300 digits: needs ~1000 bits, beyond the first try of 128.
  DecimalEnclosure d = to_decimal(ls_t11_theta_max_deg(1200), 300);
  EXPECT_TRUE(ls_t11_theta_admissible(parse_rational(d.lo)));
  EXPECT_FALSE(ls_t11_theta_admissible(parse_rational(d.hi)));
}

// The comparison with θ_max gives up at 2²⁰ bits, as its message says. θ = the lower end of an
// enclosure of θ_max at 3·2¹⁹ bits agrees with θ_max to about that many bits: beyond the budget,
// and within the reach of the next precision, 2²¹ bits (about 2.5 s of MPFR's asin).
TEST(LS_T11, AdmissibilityBeyondItsPrecisionBudgetIsRefusedByName) {
  mpq_t q;
  mpq_init(q);
  mpfr_get_q(q, ls_t11_theta_max_deg(3 << 19).lower());
  const Rational theta(q);
  mpq_clear(q);
  try {
    ls_t11_theta_admissible(theta);
    FAIL() << "decided beyond the budget";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("within 2^20 bits of precision"), std::string::npos) << e.what();
  }
}

TEST(LS_T11, GammaRefusesInadmissibleTheta) {
  // θ = 170° also has P(1) < 0, and θ < 0 breaks the uniqueness argument (review finding).
  EXPECT_THROW(ls_t11_gamma(Rational(170), prec), std::invalid_argument);
  EXPECT_THROW(ls_t11_gamma(Rational(-10), prec), std::invalid_argument);
  EXPECT_THROW(ls_t11_gamma(Rational(21), prec), std::invalid_argument);
  EXPECT_FALSE(ls_t11_gamma_bracket_verified(Rational(170), Rational(1), Rational(2), prec));
}

TEST(LS_T11, GammaNearThetaMaxIsCertifiedAboveOne) {
  DecimalEnclosure d = to_decimal(ls_t11_theta_max_deg(1200), 300);
  Rational theta = parse_rational(d.lo);
  Interval gamma = ls_t11_gamma(theta, prec);
  EXPECT_TRUE(mpfr_cmp_ui(gamma.lower(), 1) > 0);
  DecimalEnclosure g = to_decimal(gamma, 40);
  EXPECT_TRUE(ls_t11_gamma_bracket_verified(theta, parse_rational(g.lo), parse_rational(g.hi), gamma.precision()));
}

TEST(LS_T11, BracketCheckRejectsWrongBrackets) {
  Interval gamma = ls_t11_gamma(Rational(10), prec);
  DecimalEnclosure g = to_decimal(gamma, 40);
  Rational lo = parse_rational(g.lo), hi = parse_rational(g.hi);
  EXPECT_TRUE(ls_t11_gamma_bracket_verified(Rational(10), lo, hi, prec));
  EXPECT_FALSE(ls_t11_gamma_bracket_verified(Rational(10), hi, lo, prec));               // reversed
  EXPECT_FALSE(ls_t11_gamma_bracket_verified(Rational(11), lo, hi, prec));               // another θ
  EXPECT_FALSE(ls_t11_gamma_bracket_verified(Rational(10), Rational(6, 5), Rational(13, 10), prec));
}

// The root finder behind γ(θ) and BWY's γ_max needs a < b with f(a) < 0 < f(b), each part
// checked: f(x) = 4/3 − x is −2/3 at 2 and 1/3 at 1, so the reversed bracket [2, 1] has the signs
// the ends need and must still be refused, as [1, 2] must be (f(1) > 0).
TEST(LS_T11, SignChangeNeedsAnOrderedBracketWithTheSigns) {
  const auto f = [](const Interval& x) { return Interval(Rational(4, 3), 64) - x; };
  for (const auto& [a, b] : {std::pair{Rational(2), Rational(1)}, std::pair{Rational(1), Rational(2)}}) {
    try {
      enclose_sign_change(f, a, b, 64);
      ADD_FAILURE() << "bracket [" << a << ", " << b << "] accepted";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("no certified sign change"), std::string::npos) << e.what();
    }
  }
  const auto g = [](const Interval& x) { return x - Interval(Rational(4, 3), 64); };  // 4/3 is no bisection point
  EXPECT_TRUE(enclose_sign_change(g, Rational(1), Rational(2), 64).inside(Rational(1333, 1000), Rational(1334, 1000)));
  // Each end's sign is checked on its own (a campaign survivor dropped the lower end's): on
  // [3/2, 2] g is positive at both ends, 1/6 and 2/3, and on [1, 5/4] negative at both.
  for (const auto& [a, b] : {std::pair{Rational(3, 2), Rational(2)}, std::pair{Rational(1), Rational(5, 4)}})
    EXPECT_THROW(enclose_sign_change(g, a, b, 64), std::logic_error) << "[" << a << ", " << b << "]";
  // The bracket test itself: both ends' signs are needed (g(5/4) = −1/12 < 0).
  EXPECT_TRUE(brackets_sign_change(g, Rational(1), Rational(2), 64));
  EXPECT_FALSE(brackets_sign_change(g, Rational(1), Rational(5, 4), 64));
  EXPECT_FALSE(brackets_sign_change(g, Rational(3, 2), Rational(2), 64));
}

// enclose_sign_change halves its bracket until lo and hi are adjacent prec-bit numbers, which takes
// about prec steps from [1, 2]: f is evaluated at most prec + 3 times (twice for the ends, once per
// step). The roots √2, √3, √(5/2) and ∛3 end with the bracket's midpoint rounding to
// lo for some and to hi for others (ties to even); a version that did not stop at hi, or not at
// all, ran to its step bound (4 prec + 64: the 2026-12-02 campaign).
TEST(LS_T11, SignChangeStopsWhenTheBracketEndsAreAdjacent) {
  for (const auto& [k, c] : std::vector<std::pair<int, Rational>>{{2, 2}, {2, 3}, {2, Rational(5, 2)}, {3, 3}}) {
    int calls = 0;
    const mpfr_prec_t prec = 64;
    const Interval root = enclose_sign_change(
        [&, k = k, c = c](const Interval& x) {
          ++calls;
          // Evaluated at 4 prec bits, so that f decides at adjacent prec-bit points (the roots are
          // irrational): the loop ends at adjacency, not at an undecided value.
          const Interval y = x.at_precision(4 * prec);
          Interval p = y;
          for (int i = 1; i < k; ++i) p = p * y;
          return p - Interval(c, 4 * prec);
        },
        1, 2, prec);
    EXPECT_LE(calls, static_cast<int>(prec) + 3) << k << " " << c;
    Interval power = root;
    for (int i = 1; i < k; ++i) power = power * root;
    EXPECT_TRUE((power - Interval(c, prec)).has_zero()) << k << " " << c;  // it holds the root
    EXPECT_LE(root.upper_double() - root.lower_double(), 0x1p-51) << k << " " << c;  // and is tight
  }
}
