// The structure-aware mutator (geometric_mutator.hpp) does what docs/fuzzing.md says it does: over
// many seeds it writes each kind of hostile value and tie into the slots, never touches the header,
// never grows past max_size, and leaves half of the mutations to the engine's own mutator.
#include "fuzz/support/geometric_mutator.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <set>

namespace {

std::size_t fallback_calls = 0;
std::size_t count_fallback(std::uint8_t*, std::size_t size, std::size_t) {
  ++fallback_calls;
  return size;
}

}  // namespace

TEST(FuzzMutator, WritesHostileValuesAndTiesIntoTheSlotsOnly) {
  using anisocert::fuzz::mutate_geometry;
  using anisocert::fuzz::slots_of;
  const std::size_t header = 3, max_size = 3 + 8 * 12;
  bool nan = false, inf = false, subnormal = false, huge = false, negative_zero = false, tie = false, near_tie = false;
  fallback_calls = 0;
  const int runs = 20000;
  for (int seed = 0; seed < runs; ++seed) {
    std::uint8_t data[3 + 8 * 12] = {7, 8, 9};
    const double start[] = {0.1, 0.7, 1.3, 0.25, -2.5, 3.75, 0.5, 0.125};
    for (std::size_t k = 0; k < 8; ++k) anisocert::fuzz::write_slot(data, header, k, start[k]);
    const std::size_t size = mutate_geometry(data, header + 8 * 8, max_size, static_cast<unsigned>(seed), header, count_fallback);
    ASSERT_LE(size, max_size);
    ASSERT_EQ(data[0], 7);
    ASSERT_EQ(data[1], 8);
    ASSERT_EQ(data[2], 9);
    const std::vector<double> s = slots_of(data, size, header);
    for (std::size_t i = 0; i < s.size(); ++i) {
      nan = nan || std::isnan(s[i]);
      inf = inf || std::isinf(s[i]);
      subnormal = subnormal || std::fpclassify(s[i]) == FP_SUBNORMAL;
      huge = huge || std::fabs(s[i]) == DBL_MAX;
      negative_zero = negative_zero || (s[i] == 0 && std::signbit(s[i]));
      for (std::size_t j = 0; j < i; ++j) {
        if (s[i] != 0 && s[i] == s[j]) tie = true;
        if (s[i] != s[j] && std::isfinite(s[i]) && std::nextafter(s[j], s[i]) == s[i]) near_tie = true;
      }
    }
  }
  EXPECT_TRUE(nan && inf && subnormal && huge && negative_zero);
  EXPECT_TRUE(tie) << "no slot copied";
  EXPECT_TRUE(near_tie) << "no slot a few ulps from another";
  EXPECT_GT(fallback_calls, runs / 3u);
  EXPECT_LT(fallback_calls, 2u * runs / 3);
}
