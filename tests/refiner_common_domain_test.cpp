// Domain::contains(Box), the filter that decides whether a point known only by a box lies in Ω,
// against the exact test at points of the box: whenever it answers, every corner of the box, its
// centre and random rational points of it get the same exact answer.
#include "refiners/common/domain.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using namespace anisocert;
using predicates::Point2;

TEST(DomainContainsBox, AnswersOnlyWhatEveryPointOfTheBoxAgreesWith) {
  const std::vector<std::vector<Point2<double>>> polygons = {
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
      {{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}},
      {{0, 0}, {1, 0}, {1, 1}, {0.75, 1}, {0.75, 0.25}, {0.5, 0.25}, {0.5, 1}, {0.25, 1}, {0.25, 0.25}, {0, 1}},
      {{0, 0}, {2, 0}, {2.5, 1}, {1, 1.75}, {-0.5, 1}}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> where(-0.6, 2.6);
  std::uniform_int_distribution<int> width_exponent(-50, -1), fraction(0, 1 << 20);
  std::size_t answered = 0, undecided = 0;
  for (const auto& corners : polygons) {
    const refiners::common::Domain domain(corners);
    for (int round = 0; round < 4000; ++round) {
      // Boxes around corners and edge points too, where the filter must decline.
      Point2<double> c{where(rng), where(rng)};
      if (round % 4 == 0) c = corners[round / 4 % corners.size()];
      const double w = std::ldexp(1.0, width_exponent(rng)), h = round % 3 == 0 ? 0 : std::ldexp(1.0, width_exponent(rng));
      const refiners::common::Box b{c.x - w, c.x + w, c.y - h, c.y + h};
      const auto verdict = domain.contains(b);
      if (!verdict) {
        ++undecided;
        continue;
      }
      ++answered;
      for (const Point2<double>& p : {Point2<double>{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}, c})
        ASSERT_EQ(domain.contains(p), *verdict) << "box around (" << c.x << ", " << c.y << ")";
      for (int k = 0; k < 4; ++k) {
        const Rational s(fraction(rng), 1 << 20), t(fraction(rng), 1 << 20);
        const Point2<Rational> p{Rational(b.x0) + s * (Rational(b.x1) - Rational(b.x0)), Rational(b.y0) + t * (Rational(b.y1) - Rational(b.y0))};
        ASSERT_EQ(domain.contains(p), *verdict);
      }
    }
  }
  EXPECT_GT(answered, 10000u);
  EXPECT_GT(undecided, 1000u);  // boxes on the boundary
}

}  // namespace
