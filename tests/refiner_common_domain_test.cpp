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

namespace {

using anisocert::refiners::common::Domain;
using anisocert::refiners::common::DomainError;

// The message Domain gives for a PSLG on the unit square, or "" when it accepts it.
std::string refusal(const std::vector<anisocert::predicates::Point2<double>>& points, const std::vector<std::pair<int, int>>& segments) {
  try {
    (void)Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, points, segments);
    return "";
  } catch (const DomainError& e) {
    return e.what();
  }
}

// The rest of a PSLG (LS §9's input: points inside Ω, interior segments between its vertices) is
// checked exactly and refused by name: each rule of domain.hpp against one input that breaks only
// it; a slit, a segment from a corner and a point on no segment pass. X's segments are the edges,
// then the interior ones.
TEST(DomainInterior, EachRuleRefusesByName) {
  EXPECT_EQ(refusal({{0.25, 0.5}, {0.75, 0.5}, {0.5, 0.25}}, {{4, 5}, {0, 6}}), "");
  const Domain d({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0.25, 0.5}, {0.75, 0.5}}, {{4, 5}, {2, 5}});
  EXPECT_EQ(d.vertices().size(), 6u);
  EXPECT_EQ(d.segment_count(), 6u);
  EXPECT_EQ(d.segment_ends(3), (std::pair<int, int>{3, 0}));
  EXPECT_EQ(d.segment_ends(5), (std::pair<int, int>{2, 5}));
  EXPECT_TRUE(d.has_interior());
  EXPECT_FALSE(Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}).has_interior());

  const std::vector<std::pair<std::string, std::string>> cases{
      {refusal({{1.5, 0.5}}, {}), "point 0 (1.5, 0.5) lies outside the domain"},
      {refusal({{0.5, 0}}, {}), "point 0 (0.5, 0) lies on domain edge 0; make it a corner"},
      {refusal({{0.5, 0.5}, {0.5, 0.5}}, {}), "point 1 (0.5, 0.5) is point 0 (0.5, 0.5) again"},
      {refusal({{0.5, 0.5}}, {{4, 7}}), "interior segment 0 names vertex 7, but there are 5"},
      {refusal({{0.5, 0.5}}, {{4, 4}}), "joins point 0 (0.5, 0.5) to itself"},
      {refusal({{0.5, 0.5}}, {{0, 2}}), "passes through point 0 (0.5, 0.5)"},
      {refusal({}, {{1, 0}}), "interior segment 0 from corner 1 (1, 0) to corner 0 (0, 0) is domain edge 0"},
      {refusal({{0.25, 0.5}, {0.75, 0.5}, {0.5, 0.25}, {0.5, 0.75}}, {{4, 5}, {6, 7}}), "meets interior segment 0"},
      {refusal({{0.25, 0.5}, {0.75, 0.5}}, {{4, 5}, {5, 4}}), "is interior segment 0 again"},
      {refusal({{0.25, 0.5}, {0.75, 0.5}, {0.5, 0.5}}, {{4, 5}, {6, 1}}), "passes through point 2 (0.5, 0.5)"},
      {refusal({{0.1, 0.5}}, {{4, 0}}), "can be halved exactly in doubles only"},
  };
  for (const auto& [got, want] : cases) EXPECT_NE(got.find(want), std::string::npos) << "got: " << got << "\nwant: " << want;
}

// On the L: a segment across the notch, and one through the reflex corner, are refused; from a
// corner or the reflex corner into Ω is fine.
TEST(DomainInterior, SegmentsStayInsideTheDomain) {
  const std::vector<anisocert::predicates::Point2<double>> L{{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
  const auto refused = [&](const std::vector<anisocert::predicates::Point2<double>>& p, const std::vector<std::pair<int, int>>& s) {
    try {
      (void)Domain(L, p, s);
      return std::string();
    } catch (const DomainError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_NE(refused({}, {{2, 4}}).find("runs outside the domain"), std::string::npos);
  EXPECT_EQ(refused({{0.75, 0.25}}, {{6, 2}}), "");
  EXPECT_EQ(refused({{0.25, 0.25}}, {{3, 6}}), "");
  // Through reflex corner 3: touches edge 2 there, at no end of its own.
  EXPECT_NE(refused({{0.25, 0.75}, {0.75, 0.25}}, {{6, 7}}).find("meets domain edge 2 elsewhere than at a shared end"), std::string::npos);
}

}  // namespace
