// FilterInterval's outward steps against the library's std::nextafter (the specification they
// replace on the filters' hot path), on ordinary, extreme and special doubles.
#include "numbers/filter_interval.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

namespace {

using anisocert::FilterInterval;

bool same_double(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }

TEST(FilterInterval, StepsAreTheLibrarysNextafter) {
  using L = std::numeric_limits<double>;
  std::vector<double> xs = {0.0, -0.0, L::denorm_min(), -L::denorm_min(), L::min(), -L::min(), L::max(), -L::max(),
                            L::infinity(), -L::infinity(), 1.0, -1.0, 0.1, -0.1, 1e300, -1e-300};
  std::mt19937_64 rng(12);
  for (int i = 0; i < 5000; ++i) {  // random bit patterns: every exponent, both signs
    const std::uint64_t b = rng();
    double x;
    std::memcpy(&x, &b, sizeof x);
    if (!std::isnan(x)) xs.push_back(x);
  }
  for (double x : xs) {
    // std::nextafter(±0, +∞) is the least subnormal; so is ours. From −0 both go to +denorm_min.
    EXPECT_TRUE(same_double(FilterInterval::next_up(x), std::nextafter(x, L::infinity()))) << x;
    EXPECT_TRUE(same_double(FilterInterval::next_down(x), std::nextafter(x, -L::infinity()))) << x;
  }
  EXPECT_TRUE(std::isnan(FilterInterval::next_up(L::quiet_NaN())));
}

}  // namespace
