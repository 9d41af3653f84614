// Exact boundary splitting (refiners/common/exact_split): the halving count is a true lower bound,
// checked point by point in rational arithmetic (every point a + k(b − a)/2ʲ a double), and an
// exact midpoint lies exactly on the segment.
#include "numbers/rational.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/exact_split.hpp"
#include "refiners/common/segment_cells.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <limits>
#include <cmath>
#include <random>

namespace {

using anisocert::Rational;
using anisocert::rational_from_double;
using anisocert::predicates::Point2;
using anisocert::refiners::common::exact_halvings;
using anisocert::refiners::common::exact_midpoint;
using anisocert::refiners::common::split_halvings;

bool is_double(const Rational& q) { return rational_from_double(q.convert_to<double>()) == q; }

// Every point a + k(b − a)/2ʲ, 0 < k < 2ʲ, is a double (both coordinates).
bool level_is_exact(const Point2<double>& a, const Point2<double>& b, int j) {
  const Rational ax = rational_from_double(a.x), ay = rational_from_double(a.y);
  const Rational dx = rational_from_double(b.x) - ax, dy = rational_from_double(b.y) - ay;
  const Rational step = Rational(1) / Rational(1L << j);
  for (long k = 1; k < (1L << j); k += 2)
    if (!is_double(ax + dx * step * k) || !is_double(ay + dy * step * k)) return false;
  return true;
}

TEST(ExactSplit, HalvingCountIsALowerBound) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  std::uniform_int_distribution<int> bits(1, 60);
  int limited = 0;
  for (int n = 0; n < 400; ++n) {
    // Coordinates with a random number of binary digits: from dyadic with few bits to full doubles.
    auto coordinate = [&] {
      const int b = bits(rng);
      return b > 52 ? u(rng) : std::ldexp(std::round(std::ldexp(u(rng), b)), -b);
    };
    const Point2<double> a{coordinate(), coordinate()}, b{coordinate(), coordinate()};
    const int k = exact_halvings(a, b);
    ASSERT_GE(k, 0);
    if (k < 10) ++limited;
    for (int j = 1; j <= std::min(k, 10); ++j) EXPECT_TRUE(level_is_exact(a, b, j)) << "case " << n << " level " << j;
  }
  EXPECT_GT(limited, 20);  // full-precision coordinates do limit it
}

TEST(ExactSplit, ClosedForms) {
  // The unit square's edges: multiples of 2⁻ʲ in [0, 1] are doubles for j ≤ 52 (hand count:
  // E = 1, t_d = 0, so 53 − 1 + 0).
  EXPECT_EQ(exact_halvings(Point2<double>{0, 0}, Point2<double>{1, 0}), 52);
  // 0.375 = 3/8 and 1: the grid 2⁻³ at depth 0, multiples of 5/8 · 2⁻ʲ: 53 − 1 − 3 = 49.
  EXPECT_EQ(exact_halvings(Point2<double>{1, 0.375}, Point2<double>{0.375, 1}), 49);
  // An end with all 53 bits (u = 1 + 2⁻⁵², E − t_u = 53 exactly) and w = u + 2⁻²⁰: the points
  // u + k 2⁻²⁰⁻ʲ are multiples of 2⁻⁵² in [1, 2), doubles, for j ≤ 32 (53 − 1 − 20; campaign mutant
  // 170 refused every halving when E − t_u = 53).
  EXPECT_EQ(exact_halvings(Point2<double>{1 + 0x1p-52, 0}, Point2<double>{1 + 0x1p-52 + 0x1p-20, 0}), 32);
  const Rational full = rational_from_double(1 + 0x1p-52);
  EXPECT_TRUE(is_double(full + rational_from_double(0x1p-52)));    // the first point of level 32
  EXPECT_FALSE(is_double(full + rational_from_double(0x1p-53)));   // and of level 33
  // 0.4 (an odd multiple of 2⁻⁵⁴) and 1: no double point with y ∈ [1/2, 1), so not even once.
  EXPECT_EQ(exact_halvings(Point2<double>{1, 0.4}, Point2<double>{0.4, 1}), 0);
  EXPECT_FALSE(exact_midpoint(Point2<double>{1, 0.4}, Point2<double>{0.4, 1}));
  EXPECT_FALSE(level_is_exact({1, 0.4}, {0.4, 1}, 1));
  // Review findings: subnormal coordinates (2⁻¹⁰⁷⁵ is not a double), non-finite ones, a
  // difference beyond the doubles, and a sum that overflows although the midpoint is a double.
  EXPECT_EQ(exact_halvings(Point2<double>{0, 0}, Point2<double>{0x1p-1074, 0}), 0);
  EXPECT_EQ(exact_halvings(Point2<double>{0, 0}, Point2<double>{0x1p-1070, 0}), 4);  // multiples of 2⁻¹⁰⁷⁴ below 2⁻¹⁰⁷⁰
  EXPECT_EQ(exact_halvings(Point2<double>{0, 0}, Point2<double>{INFINITY, 0}), 0);
  EXPECT_EQ(exact_halvings(Point2<double>{INFINITY, 0}, Point2<double>{INFINITY, 1}), 0);  // equal but not finite: no halving
  EXPECT_EQ(exact_halvings(Point2<double>{NAN, 0}, Point2<double>{1, 1}), 0);
  EXPECT_EQ(exact_halvings(Point2<double>{-0x1p1023, 0}, Point2<double>{0x1p1023, 0}), 0);
  EXPECT_FALSE(exact_midpoint(Point2<double>{0, 0}, Point2<double>{0x1p-1074, 0}));
  EXPECT_FALSE(exact_midpoint(Point2<double>{0, 0}, Point2<double>{NAN, 0}));
  const double big = std::numeric_limits<double>::max();
  const auto m = exact_midpoint(Point2<double>{big, 0}, Point2<double>{big, 0});
  ASSERT_TRUE(m);
  EXPECT_EQ(m->x, big);
  const auto m2 = exact_midpoint(Point2<double>{big, 0}, Point2<double>{std::nextafter(std::nextafter(big, 0), 0), 0});
  ASSERT_TRUE(m2);
  EXPECT_EQ(m2->x, std::nextafter(big, 0));
}

TEST(ExactSplit, MidpointIsExactlyOnTheSegmentOrRefused) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-2, 2);
  int refused = 0, given = 0;
  for (int n = 0; n < 2000; ++n) {
    const int b = n % 2 ? 60 : 20;
    auto coordinate = [&] { return b > 52 ? u(rng) : std::ldexp(std::round(std::ldexp(u(rng), b)), -b); };
    const Point2<double> a{coordinate(), coordinate()}, c{coordinate(), coordinate()};
    const Rational mx = (rational_from_double(a.x) + rational_from_double(c.x)) / 2;
    const Rational my = (rational_from_double(a.y) + rational_from_double(c.y)) / 2;
    const auto m = exact_midpoint(a, c);
    if (m) {
      ++given;
      EXPECT_EQ(rational_from_double(m->x), mx);
      EXPECT_EQ(rational_from_double(m->y), my);
    } else {
      ++refused;
      EXPECT_FALSE(is_double(mx) && is_double(my)) << "case " << n << ": an exact midpoint was refused";
    }
  }
  EXPECT_GT(given, 500);
  EXPECT_GT(refused, 80);
}

// A domain is accepted exactly when every edge can be halved min_halvings = 30 times. Closed form
// (the count's formula 53 − E + t_d, exact_split.cpp): from 0 to 1 + 2⁻²² the magnitude has E = 1
// and the difference's last bit is 2⁻²², so 53 − 1 − 22 = 30 halvings: accepted, at the bound;
// to 1 + 2⁻²³, 29: refused, naming the count.
TEST(ExactSplit, DomainAtTheHalvingBoundIsAccepted) {
  using anisocert::refiners::common::Domain;
  const double at = 1 + std::ldexp(1.0, -22), below = 1 + std::ldexp(1.0, -23);
  EXPECT_EQ(exact_halvings(Point2<double>{0, 0}, Point2<double>{at, 0}), 30);
  EXPECT_EQ(exact_halvings(Point2<double>{0, 0}, Point2<double>{below, 0}), 29);
  EXPECT_NO_THROW(Domain({{0, 0}, {at, 0}, {0, 1}}));
  try {
    Domain({{0, 0}, {below, 0}, {0, 1}});
    ADD_FAILURE() << "a domain edge with 29 exact halvings was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("only 29 times (30 needed"), std::string::npos) << e.what();
  }
}

}  // namespace

// A mesh's boundary vertex has all 53 bits (`refine --from`): the edge from (0, 0) to (x, 0), x the
// double nearest 0.0131408939483 (an odd multiple of 2⁻⁵⁹), has no grid point a + j2⁻ᵏ(b − a)
// that is a double beyond the first halving, but every double between its ends lies on it:
// split_halvings counts ilogb(x) − ilogb(ulp(x)) − 2 = −7 + 59 − 2 = 50 halvings, and the split
// points are doubles of the edge. The coarsest double within 1/64 of the edge around its midpoint
// x/2 ≈ 0.0065704 (the window [0.0063651, 0.0067758]) is 27/4096: no multiple of 2⁻¹¹ lies in
// it (13/2048 and 14/2048 do not), one of 2⁻¹² does.
TEST(ExactSplit, AxisParallelEdgesOfFullMantissaVerticesSplitAtTheirDoubles) {
  const double x = 0.0131408939483;
  const Point2<double> a{0, 0}, b{x, 0};
  EXPECT_EQ(exact_halvings(a, b), 0);
  EXPECT_FALSE(level_is_exact(a, b, 2));
  EXPECT_EQ(split_halvings(a, b), 50);
  EXPECT_EQ(split_halvings(Point2<double>{0.25, x}, Point2<double>{0.25, 0}), 50);  // the same upright
  EXPECT_EQ(split_halvings(Point2<double>{INFINITY, 0}, Point2<double>{INFINITY, 1}), 0);
  EXPECT_EQ(split_halvings(Point2<double>{0, 0}, Point2<double>{x, x}), exact_halvings(Point2<double>{0, 0}, Point2<double>{x, x}));  // slanted
  const auto z = anisocert::refiners::common::split_point(a, b, Rational(1, 4), Rational(3, 4), Rational(1, 3));
  ASSERT_TRUE(z);
  EXPECT_EQ(z->y, 0);
  EXPECT_EQ(z->x, (rational_from_double(x) / 3).convert_to<double>());  // the double nearest x/3
  const auto c = anisocert::refiners::common::coarse_split_point(a, b, Rational(0), Rational(1), Rational(1, 2), Rational(1, 64));
  ASSERT_TRUE(c);
  EXPECT_EQ(c->y, 0);
  EXPECT_EQ(c->x, 27.0 / 4096);
  // A window that holds no double is refused, not rounded into it: x/7 lies a seventh of an ulp
  // or more from every double (x = m 2⁻⁵⁹ with m not divisible by 7; the doubles near x/7 are
  // 2⁻⁶² apart), far more than the window's 2⁻⁶² x on either side.
  ASSERT_NE(denominator(rational_from_double(x) * Rational(anisocert::Integer(1) << 59) / 7), 1);
  EXPECT_FALSE(anisocert::refiners::common::coarse_split_point(a, b, Rational(0), Rational(1), Rational(1, 7), Rational(1, 1) / Rational(1L << 62)));
}
