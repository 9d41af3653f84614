// FilterInterval's outward steps against the library's std::nextafter (the specification they
// replace on the filters' hot path), and its product by a double against the general product by
// the point interval, on ordinary, extreme and special doubles.
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

// The fast path must give the general product's interval, endpoint for endpoint: the same
// enclosure, and the whole line where 0 · ∞ occurs.
TEST(FilterInterval, ProductByADoubleIsTheProductByItsPoint) {
  using L = std::numeric_limits<double>;
  std::vector<double> xs = {0.0, -0.0, L::denorm_min(), -L::min(), L::max(), -L::max(), L::infinity(),
                            -L::infinity(), 1.0, -3.5, 0.1, 1e300, -1e-300};
  std::mt19937_64 rng(13);
  for (int i = 0; i < 300; ++i) {
    const std::uint64_t b = rng();
    double x;
    std::memcpy(&x, &b, sizeof x);
    if (!std::isnan(x)) xs.push_back(x);
  }
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
    const FilterInterval a(std::min(xs[i], xs[i + 1]), std::max(xs[i], xs[i + 1]));
    for (double s : xs) {
      const FilterInterval general = a * FilterInterval(s), fast = a * s, flipped = s * a;
      EXPECT_TRUE(same_double(fast.lo, general.lo) && same_double(fast.hi, general.hi)) << a.lo << ' ' << a.hi << ' ' << s;
      EXPECT_TRUE(same_double(flipped.lo, general.lo) && same_double(flipped.hi, general.hi));
    }
  }
}

}  // namespace
