// ExactDouble (numbers/exact_double.hpp) against rationals: an operation it calls exact is the
// rational result, and one whose rational result is its double (no rounding, overflow or, for
// products, a result below 2^−968) it calls exact, so that the stage decides what it can. Then
// whole kernels: the predicates' double evaluations on grids round nowhere, and any evaluation it
// calls exact has the rational evaluation's value.
#include "numbers/exact_double.hpp"
#include "predicates/incircle.hpp"
#include "predicates/metric_dot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using anisocert::ExactDouble;
using anisocert::Rational;

// A double with few or many significant bits, over the whole exponent range and near its ends.
double draw(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 5), bits(1, 53), exponent(-1100, 1024), small(-8, 8);
  const int k = kind(rng);
  if (k == 0) return 0;
  const int b = bits(rng);
  const double m = std::ldexp(static_cast<double>(rng() >> (64 - b)), -b);  // [0, 1) with b bits
  const int e = k <= 2 ? small(rng) : k == 3 ? exponent(rng) : k == 4 ? 1000 + small(rng) % 30 : -1000 - small(rng) % 80;
  const double x = std::ldexp(m, e);
  return rng() & 1 ? -x : x;
}

// The rational of a finite double (an infinity or NaN: none).
std::optional<Rational> rational(double x) {
  if (!std::isfinite(x)) return std::nullopt;
  return Rational(x);
}

TEST(ExactDouble, EachOperationIsExactExactlyWhenItsDoubleIsTheRationalResult) {
  std::mt19937_64 rng(20261202);
  int exact[3] = {0, 0, 0}, inexact[3] = {0, 0, 0};
  for (int n = 0; n < 300000; ++n) {
    const double a = draw(rng), b = draw(rng);
    const ExactDouble A(a), B(b);
    const ExactDouble r[3] = {A + B, A - B, A * B};
    const Rational q[3] = {Rational(a) + Rational(b), Rational(a) - Rational(b), Rational(a) * Rational(b)};
    const double plain[3] = {a + b, a - b, a * b};
    for (int op = 0; op < 3; ++op) {
      ASSERT_EQ(r[op].value(), plain[op]) << "not the double evaluation";  // NaN never occurs: finite inputs
      const auto d = rational(r[op].value());
      const bool is_exact = d && *d == q[op];
      if (r[op].exact()) {
        ASSERT_TRUE(is_exact) << a << " op " << op << " " << b << " called exact";
        ++exact[op];
      } else {
        // Products below 2^−968 are left to the expansions even when exact (their error term may underflow).
        const bool tiny_product = op == 2 && plain[op] != 0 && std::fabs(plain[op]) < 0x1p-968;
        ASSERT_FALSE(is_exact && !tiny_product) << a << " op " << op << " " << b << " is exact but not called so";
        ++inexact[op];
      }
    }
  }
  for (int op = 0; op < 3; ++op) {  // both outcomes are common: the draws reach both
    EXPECT_GT(exact[op], 30000) << op;
    EXPECT_GT(inexact[op], 30000) << op;
  }
}

TEST(ExactDouble, NonFiniteInputsAndOverflowAreNotExact) {
  const double inf = std::numeric_limits<double>::infinity(), big = std::numeric_limits<double>::max();
  EXPECT_FALSE(ExactDouble(inf).exact());
  EXPECT_FALSE(ExactDouble(std::nan("")).exact());
  EXPECT_FALSE((ExactDouble(big) + ExactDouble(big)).exact());
  EXPECT_FALSE((ExactDouble(big) * ExactDouble(2)).exact());
  EXPECT_FALSE((ExactDouble(0) * ExactDouble(inf)).exact());
  EXPECT_FALSE((ExactDouble(0x1p-600) * ExactDouble(0x1p-600)).exact());  // underflows to 0
  EXPECT_TRUE((ExactDouble(0) * ExactDouble(0x1p-600)).exact());
  EXPECT_TRUE((-ExactDouble(big) + ExactDouble(big)).exact());
}

// The predicates' kernels on the points of a grid (right angles, cocircular quadruples: the calls
// that reach this stage when a refiner keeps a grid) evaluate exactly and agree with rationals.
// On points of a few bits at scales 2^−30 to 2^30 some evaluations round and some do not; those
// called exact have the rational value.
TEST(ExactDouble, KernelsOnGridsAreExactAndAgreeWithRationals) {
  using anisocert::predicates::InCircleKernel;
  using anisocert::predicates::MetricDotKernel;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coordinate(0, 64), scale(-30, 30);
  int zero_on_grid = 0, exact_scaled = 0, inexact_scaled = 0;
  for (int n = 0; n < 20000; ++n) {
    const bool scaled = n % 2 == 1;
    const auto draw_few_bits = [&] { return std::ldexp(coordinate(rng), scaled ? scale(rng) : -6); };
    const auto check = [&](auto kernel) {
      using K = decltype(kernel);
      std::array<ExactDouble, K::arity> d;
      std::array<Rational, K::arity> q;
      for (std::size_t i = 0; i < K::arity; ++i) {
        const double x = draw_few_bits();
        d[i] = x, q[i] = Rational(x);
      }
      const ExactDouble v = K::template eval<ExactDouble>(d);
      if (!scaled) {
        ASSERT_TRUE(v.exact());
        zero_on_grid += v.value() == 0;
      } else {
        (v.exact() ? exact_scaled : inexact_scaled)++;
      }
      if (v.exact()) {
        ASSERT_EQ(Rational(v.value()), K::template eval<Rational>(q));
      }
    };
    check(InCircleKernel{});
    check(MetricDotKernel{});
  }
  EXPECT_GT(zero_on_grid, 10);  // 17: random grid points are seldom cocircular or at right angles
  EXPECT_GT(exact_scaled, 100);
  EXPECT_GT(inexact_scaled, 100);
}

}  // namespace
