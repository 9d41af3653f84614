// Exact conic-conic intersection against closed forms (each expected point worked out by
// hand in the comment), and exact signs at the intersection points, including the trap that
// CGAL 5.5's Algebraic_kernel_d_2::Sign_at_2 falls into (DESIGN.md § Numbers).

#include "oracle/algebraic/common_points.hpp"
#include "oracle/algebraic/certified_roots.hpp"
#include "oracle/algebraic/conic_intersection.hpp"
#include "oracle/algebraic/narrowed_box.hpp"
#include "oracle/algebraic/polynomial.hpp"
#include "oracle/algebraic/shared_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using anisocert::parse_rational;
using anisocert::Rational;
using namespace anisocert::oracle;
using anisocert::Sign;
using anisocert::sign_of;

namespace {

ConicIntersection run(const Conic& A, const Conic& B) { return intersect(A, B); }

void expect_point(const IntersectionPoint& p, const char* x, const char* y, int m, int digits = 25) {
  EXPECT_EQ(p.point.x_decimal(digits), x);
  EXPECT_EQ(p.point.y_decimal(digits), y);
  EXPECT_EQ(p.multiplicity, m);
}


}  // namespace

TEST(ConicIntersection, FourRealPoints) {
  // x² + y² = 1 and x² + 4y² = 2: 3y² = 1, x² = 2/3: (±√(2/3), ±1/√3).
  const auto r = run({1, 0, 1, 0, 0, -1}, {1, 0, 4, 0, 0, -2});
  ASSERT_FALSE(r.shared_component);
  ASSERT_EQ(r.points.size(), 4u);
  // √(2/3) = 0.81649658092772603273242802…, 1/√3 = 0.57735026918962576450914878… (25 digits, trailing 0 dropped)
  expect_point(r.points[0], "-0.816496580927726032732428", "-0.5773502691896257645091488", 1);
  expect_point(r.points[3], "0.816496580927726032732428", "0.5773502691896257645091488", 1);
}

TEST(ConicIntersection, TwoTangencies) {
  // x² + y² = 1 and x² + 4y² = 1 touch at (±1, 0), each of multiplicity 2.
  const auto r = run({1, 0, 1, 0, 0, -1}, {1, 0, 4, 0, 0, -1});
  ASSERT_EQ(r.points.size(), 2u);
  expect_point(r.points[0], "-1", "0", 2);
  expect_point(r.points[1], "1", "0", 2);
  // Externally tangent circles x² + y² = 1 and (x − 2)² + y² = 1 at (1, 0).
  const auto t = run({1, 0, 1, 0, 0, -1}, {1, 0, 1, -4, 0, 3});
  ASSERT_EQ(t.points.size(), 1u);
  expect_point(t.points[0], "1", "0", 2);
}

TEST(ConicIntersection, NoRealPointAndIdenticalConics) {
  EXPECT_TRUE(run({1, 0, 1, 0, 0, -1}, {1, 0, 1, 0, 0, -4}).points.empty());  // concentric circles
  EXPECT_TRUE(run({1, 0, 1, 0, 0, 1}, {1, 0, -1, 0, 0, -1}).points.empty());  // an empty conic
  const auto same = run({1, 0, 1, 0, 0, -1}, {2, 0, 2, 0, 0, -2});            // proportional: identical
  EXPECT_TRUE(same.shared_component);
  EXPECT_TRUE(same.points.empty());
}

TEST(ConicIntersection, LinePairComponents) {
  // x² − y² = (x − y)(x + y) and xy: only the origin, where both are singular: multiplicity 4.
  const auto r = run({1, 0, -1, 0, 0, 0}, {0, 1, 0, 0, 0, 0});
  ASSERT_EQ(r.points.size(), 1u);
  expect_point(r.points[0], "0", "0", 4);
  // x(y − 1) and y(x − 1): (0, 0) and (1, 1), transversal.
  const auto s = run({0, 1, 0, -1, 0, 0}, {0, 1, 0, 0, -1, 0});
  ASSERT_EQ(s.points.size(), 2u);
  expect_point(s.points[0], "0", "0", 1);
  expect_point(s.points[1], "1", "1", 1);
  // x(y − 1) and x²: the line x = 0 is shared.
  EXPECT_TRUE(run({0, 1, 0, -1, 0, 0}, {1, 0, 0, 0, 0, 0}).shared_component);
  // (x − 1)(x − 2) and y² − 1: the four points (1, ±1), (2, ±1).
  const auto g = run({1, 0, 0, -3, 0, 2}, {0, 0, 1, 0, 0, -1});
  ASSERT_EQ(g.points.size(), 4u);
  expect_point(g.points[1], "1", "1", 1);
  expect_point(g.points[2], "2", "-1", 1);
}

TEST(ConicIntersection, LineTangentToHyperbola) {
  const auto r = run({1, 0, -1, 0, 0, -1}, {0, 0, 0, 1, 0, -1});  // x² − y² = 1 and x = 1
  ASSERT_EQ(r.points.size(), 1u);
  expect_point(r.points[0], "1", "0", 2);
}

TEST(ConicIntersection, RejectsTheZeroConic) {
  EXPECT_THROW(run({0, 0, 0, 0, 0, 0}, {1, 0, 1, 0, 0, -1}), std::invalid_argument);
  EXPECT_TRUE(run({0, 0, 0, 0, 0, 5}, {1, 0, 1, 0, 0, -1}).points.empty());  // 5 = 0: no point
}

TEST(AlgebraicPoints, SameVertexFromDifferentPairs) {
  // (1, 1) is on x² + y² = 2, on xy = 1 and on x = y: reached from two different pairs.
  const auto a = run({1, 0, 1, 0, 0, -2}, {0, 1, 0, 0, 0, -1});  // tangent at (±1, ±1)
  const auto b = run({1, 0, 1, 0, 0, -2}, {0, 0, 0, 1, -1, 0});  // x = y: (±1, ±1)
  ASSERT_EQ(a.points.size(), 2u);
  ASSERT_EQ(b.points.size(), 2u);
  EXPECT_TRUE(same_point(a.points[1].point, b.points[1].point));
  EXPECT_FALSE(same_point(a.points[0].point, b.points[1].point));
  EXPECT_TRUE(same_point(a.points[1].point, AlgebraicPoint::rational(1, 1)));
  // A sample point of x² + y² = 2 above x = 1 is (1, ±1).
  const auto sample = AlgebraicPoint::on_conic_at({1, 0, 1, 0, 0, -2}, 1);
  ASSERT_EQ(sample.size(), 2u);
  EXPECT_TRUE(same_point(sample[1], a.points[1].point));
  // Coordinates compare exactly: √(2/3) (from the circle/ellipse pair) against 4/5 and 5/6.
  const auto c = run({1, 0, 1, 0, 0, -1}, {1, 0, 4, 0, 0, -2});
  EXPECT_EQ(compare_x(c.points[3].point, AlgebraicPoint::rational(Rational(4, 5), 0)), Sign::positive);
  EXPECT_EQ(compare_x(c.points[3].point, AlgebraicPoint::rational(Rational(5, 6), 0)), Sign::negative);
}

TEST(RealAlgebraic, DecimalsAreCorrectlyRounded) {
  // √2 = 1.41421356237309504880168872420969807856967187537694…
  const auto r = real_roots(Polynomial(std::vector<Rational>{-2, 0, 1}));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].decimal(30), "1.41421356237309504880168872421");
  EXPECT_EQ(r[0].decimal(5), "-1.4142");
  // Exact rational roots, powers of ten and ties: x = 1/10, x = 10, x = 0.125 at 2 digits (even).
  EXPECT_EQ(real_roots(Polynomial(std::vector<Rational>{Rational(-1, 10), 1}))[0].decimal(10), "0.1");
  EXPECT_EQ(real_roots(Polynomial(std::vector<Rational>{-100, 0, 1}))[1].decimal(10), "10");
  EXPECT_EQ(real_roots(Polynomial(std::vector<Rational>{Rational(-1, 8), 1}))[0].decimal(2), "0.12");
}

TEST(ConicIntersection, NearlyCoincidentCoordinatesFromAReview) {
  // A = (x − δy − 1/3)(x − 5), B = (3x − 2y − 1)(x + (δ − 14/3)y + 13/3 − 2δ): common points
  // (1/3, 0), (1/3 + δ, 1), (5, 2), (5, 7) (by substitution). With δ = 2⁻⁶⁰⁰ the first two x
  // differ by 2⁻⁶⁰⁰: isolation needs ~600 halvings (a cap of 5000 used to throw near δ = 2⁻⁵¹⁰⁰).
  const Rational d = Rational(1) / Rational(boost::multiprecision::pow(anisocert::Integer{2}, 600));
  const Conic A{1, -d, 0, Rational(-16, 3), 5 * d, Rational(5, 3)};
  const Conic B{3, 3 * d - 16, Rational(28, 3) - 2 * d, 12 - 6 * d, 3 * d - 4, 2 * d - Rational(13, 3)};
  const auto r = run(A, B);
  ASSERT_EQ(r.points.size(), 4u);
  EXPECT_TRUE(same_point(r.points[0].point, AlgebraicPoint::rational(Rational(1, 3), 0)));
  EXPECT_TRUE(same_point(r.points[1].point, AlgebraicPoint::rational(Rational(1, 3) + d, 1)));
  EXPECT_EQ(compare_x(r.points[0].point, r.points[1].point), Sign::negative);
  EXPECT_TRUE(same_point(r.points[3].point, AlgebraicPoint::rational(5, 7)));
}

TEST(RealAlgebraic, HugeMagnitudesPrintQuickly) {
  // √(2·10¹⁰⁰⁰⁰) = √2 · 10⁵⁰⁰⁰: the decade is found from digit counts, not by counting.
  const Rational big(boost::multiprecision::pow(anisocert::Integer{10}, 10000));
  const auto r = real_roots(Polynomial(std::vector<Rational>{-2 * big, 0, 1}));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].decimal(10), "1.414213562e5000");
}

// Two bisectors of a property test's case (LS_T7, seed 16030698392319408430) that share the line
// y = −4: A = x·(y/10 + 2/5) + 253/1400 y² + 317/700 y − 27/25 and
// B = 39/400 y² + 61/200 y − 17/50 = (39/400)(y + 4)(y − 34/39). Their one isolated common point
// is (307/273, 34/39) (A at y = 34/39 is linear in x). The certified search finds it in a box
// away from the line; building it exactly must not ask the intersection, which reports the
// shared component, for a point it does not list.
TEST(SharedLine, IsolatedPointOfCurvesSharingALineIsBuiltFromItsCertifiedBox) {
  const Conic A{0, Rational(1, 10), Rational(253, 1400), Rational(2, 5), Rational(317, 700), Rational(-27, 25)};
  const Conic B{0, 0, Rational(39, 400), 0, Rational(61, 200), Rational(-17, 50)};
  EXPECT_TRUE(intersect(A, B).shared_component);
  const std::optional<Conic> G = common_line(A, B);
  ASSERT_TRUE(G.has_value());
  EXPECT_EQ((*G)(5, -4), 0);
  EXPECT_EQ((*G)(-3, -4), 0);
  const auto is = [](const RealAlgebraic& v, const Rational& q) { return compare(v, RealAlgebraic::rational(q)) == Sign::zero; };
  const std::vector<AlgebraicPoint> isolated = isolated_common_points(A, B);
  ASSERT_EQ(isolated.size(), 1u);
  EXPECT_TRUE(is(isolated[0].x(), Rational(307, 273)) && is(isolated[0].y(), Rational(34, 39)));
  const CommonPoints found = common_points(A, B, {{1, 1.25}, {0.75, 1}}, Rational(1, 1000000));
  ASSERT_FALSE(found.shared_component);
  ASSERT_EQ(found.points.size(), 1u);
  const AlgebraicPoint& p = found.points[0].exact();
  EXPECT_TRUE(is(p.x(), Rational(307, 273)) && is(p.y(), Rational(34, 39)));
}

// Proportional conics share everything: no isolated point, and no error.
TEST(SharedLine, ProportionalConicsHaveNoIsolatedPoint) {
  const Conic A{1, 0, 1, 0, 0, -1}, B{2, 0, 2, 0, 0, -2};
  EXPECT_TRUE(isolated_common_points(A, B).empty());
}

// A guard no other test reached (a survivor of issue 18's mutation campaign): dividing by the zero
// polynomial is an error, not a read of its undefined leading coefficient.
TEST(Polynomial, DivisionByZeroIsAnError) {
  EXPECT_THROW(divide(Polynomial(std::vector<Rational>{1, 2}), Polynomial(std::vector<Rational>{})), std::domain_error);
}

// A search box with an infinite side is left to the exact path (no certified answer), whichever
// side it is.
TEST(CertifiedRoots, SearchBoxWithAnInfiniteSideIsLeftToTheExactPath) {
  const double inf = std::numeric_limits<double>::infinity();
  // x² + y² − 1 and x − y: two common points, (±1/√2, ±1/√2).
  const IntervalConic A = IntervalConic::around({1, 0, 1, 0, 0, -1}), B = IntervalConic::around({0, 0, 0, 1, -1, 0});
  ASSERT_TRUE(certified_common_roots(A, B, {{-2, 2}, {-2, 2}}).has_value());
  for (const IntervalBox& box : {IntervalBox{{-inf, 2}, {-2, 2}}, IntervalBox{{-2, inf}, {-2, 2}},
                                 IntervalBox{{-2, 2}, {-inf, 2}}, IntervalBox{{-2, 2}, {-2, inf}}})
    EXPECT_FALSE(certified_common_roots(A, B, box).has_value());
  // A box the coefficient bounds alone exclude, even with an infinite side: xy − y² + y − 1 and
  // x − y meet only at (1, 1) (x = y leaves y − 1 = 0), outside [1, 2] × [−∞, −1], and A's
  // interval over the box is far from 0. Still no answer: the search does not take infinite sides
  // (issue 38's independent read found that the low y end was unchecked).
  const IntervalConic C = IntervalConic::around({0, 1, -1, 0, 1, -1}), D = IntervalConic::around({0, 0, 0, 1, -1, 0});
  ASSERT_TRUE(certified_common_roots(C, D, {{1, 2}, {-2, -1}}).has_value());
  EXPECT_FALSE(certified_common_roots(C, D, {{1, 2}, {-inf, -1}}).has_value());
}

// A box that the natural interval extension of A excludes is root-free at once: x² + y² − 1 is at
// least 1 on [−10, −1]², so the search answers an empty list. (A version whose interval square of
// a negative interval was [0, max²] could not exclude it, and certified the common point
// (−1/√2, −1/√2) of the nearby circle and line instead: the 2026-12-02 campaign, told apart by an
// independent reader.)
TEST(CertifiedRoots, ABoxTheNaturalExtensionExcludesHasNoRoot) {
  const auto roots = certified_common_roots(IntervalConic::around({1, 0, 1, 0, 0, -1}), IntervalConic::around({0, 0, 0, 1, -1, 0}),
                                            {{-10, -1}, {-10, -1}});
  ASSERT_TRUE(roots.has_value());
  EXPECT_TRUE(roots->empty());
}

// A certified root near the search box, never far from it: x = 0 and y = (5/8)x² − 1/8 meet at
// (0, −1/8) only, 1/8 below the box [−1, 1] × [0, 1/64]. Newton's iterate from a sub-box lands
// there, far beyond the sub-box's width, and is not a root of the box (issue 38's independent read
// found a version that listed it). Every box the answer gives meets the search box enlarged by
// its width on each side (certified_roots.hpp), here by twice that.
TEST(CertifiedRoots, RootsFoundFarBelowTheSearchBoxAreNotListed) {
  const IntervalConic A = IntervalConic::around({0, 0, 0, 1, 0, 0});
  const IntervalConic B = IntervalConic::around({Rational(-5, 8), 0, 0, 0, 1, Rational(1, 8)});
  const IntervalBox search{{-1, 1}, {0, 1.0 / 64}};
  const auto roots = certified_common_roots(A, B, search);
  ASSERT_TRUE(roots.has_value());
  EXPECT_TRUE(roots->empty());
  for (const IntervalBox& r : *roots) {
    const double wx = search.x.hi - search.x.lo, wy = search.y.hi - search.y.lo;
    EXPECT_FALSE(r.x.hi < search.x.lo - 2 * wx || r.x.lo > search.x.hi + 2 * wx || r.y.hi < search.y.lo - 2 * wy ||
                 r.y.lo > search.y.hi + 2 * wy);
  }
}

// The second filter stage (narrowed_box.hpp) against the exact path: circles with rational
// centres and radii² meet at irrational points (x² + y² = 1 and x = y at ±1/√2; and random
// pairs), each certified box narrowed by Krawczyk's operator in MPFI holds the exact point
// (compared exactly with the box's ends) and is at most five doubles wide per side.
TEST(NarrowedBox, HoldsTheExactCommonPointInAFewUlps) {
  std::mt19937 rng(38);
  std::uniform_int_distribution<int> coordinate(-40, 40), radius(10, 60);
  int narrowed = 0;
  for (int k = 0; k < 60; ++k) {
    const Rational ax(coordinate(rng), 16), ay(coordinate(rng), 16), bx(coordinate(rng), 16), by(coordinate(rng), 16);
    const Rational ra(radius(rng), 16), rb(radius(rng), 16);
    const Conic A = k == 0 ? Conic{1, 0, 1, 0, 0, -1} : Conic{1, 0, 1, -2 * ax, -2 * ay, ax * ax + ay * ay - ra * ra};
    const Conic B = k == 0 ? Conic{0, 0, 0, 1, -1, 0} : Conic{1, 0, 1, -2 * bx, -2 * by, bx * bx + by * by - rb * rb};
    const auto boxes = certified_common_roots(IntervalConic::around(A), IntervalConic::around(B), {{-20, 20}, {-20, 20}});
    if (!boxes) continue;
    const ConicIntersection exact = intersect(A, B);
    ASSERT_EQ(boxes->size(), exact.points.size());
    for (std::size_t i = 0; i < boxes->size(); ++i) {
      const auto n = narrowed_box(A, B, (*boxes)[i]);
      if (!n) continue;
      ++narrowed;
      const auto within = [](const RealAlgebraic& v, const anisocert::FilterInterval& side) {
        return compare(v, RealAlgebraic::rational(Rational(side.lo))) != Sign::negative &&
               compare(v, RealAlgebraic::rational(Rational(side.hi))) != Sign::positive;
      };
      const auto held = std::count_if(exact.points.begin(), exact.points.end(), [&](const IntersectionPoint& p) {
        return within(p.point.x(), n->x) && within(p.point.y(), n->y);
      });
      EXPECT_EQ(held, 1) << "pair " << k << ", box " << i;
      for (const auto& side : {n->x, n->y}) {
        double lo = side.lo;
        for (int step = 0; step < 5 && lo < side.hi; ++step) lo = std::nextafter(lo, side.hi);
        EXPECT_GE(lo, side.hi) << "pair " << k << ": [" << side.lo << ", " << side.hi << "] is wider than five doubles";
      }
    }
  }
  EXPECT_GT(narrowed, 40);
}

// Where the Jacobian is singular (x² + y² = 1 touching y = 1 at (0, 1)) nothing is proved: the
// caller decides exactly.
TEST(NarrowedBox, TangentCurvesAreLeftToTheExactPath) {
  EXPECT_FALSE(narrowed_box({1, 0, 1, 0, 0, -1}, {0, 0, 0, 0, 1, -1}, {{-1e-3, 1e-3}, {1 - 1e-3, 1 + 1e-3}}).has_value());
}

// The filtered common points come sorted by x, then y (common_points.hpp), as the exact ones do:
// x² + y² = 1 and x = 1/3 meet at (1/3, ∓√8/3), the lower first. Two copies of one filtered point
// compare equal without their exact point being built ("two copies of one construction are equal
// without arithmetic", docs/oracle.md § Filters): x² + y² = 1 and y = 2x meet at ±(1/√5, 2/√5),
// whose boxes are apart, so nothing needs an exact point. (The 2026-12-02 campaign's mutants
// sorting y downwards and comparing copies exactly survived.)
TEST(CommonPoints, FilteredPointsAreSortedAndCopiesCompareWithoutExactPoints) {
  FilterContext context;
  const FilterScope scope(context);
  const CommonPoints c = common_points({1, 0, 1, 0, 0, -1}, {0, 0, 0, 1, 0, Rational(-1, 3)}, {{-2, 2}, {-2, 2}}, Rational(1, 1024));
  ASSERT_EQ(c.points.size(), 2u);
  EXPECT_EQ(context.counts.roots_filtered, 1u);  // the certified path, not the exact one
  EXPECT_EQ(compare_y(c.points[0], c.points[1]), Sign::negative);
  EXPECT_LT(c.points[0].y.hi, 0.0);
  const CommonPoints d = common_points({1, 0, 1, 0, 0, -1}, {0, 0, 0, 2, -1, 0}, {{-2, 2}, {-2, 2}}, Rational(1, 1024));
  ASSERT_EQ(d.points.size(), 2u);
  const std::uint64_t built = context.counts.exact_points;
  const LocatedPoint copy = d.points[1];
  EXPECT_EQ(compare_x(copy, d.points[1]), Sign::zero);
  EXPECT_EQ(compare_y(copy, d.points[1]), Sign::zero);
  EXPECT_TRUE(same_point(copy, d.points[1]));
  EXPECT_EQ(compare_x(d.points[0], copy), Sign::negative);
  EXPECT_EQ(context.counts.exact_points, built);
}
