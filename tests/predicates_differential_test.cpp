// Filtered against exact, in the manner of CGAL's Kernel_checker: every kernel, on random
// inputs over a wide range of magnitudes, on exactly degenerate inputs (representable as
// doubles, so the double path sees them exactly) and on inputs a few ulps away.
// Zero disagreements allowed.

#include "predicates/angle.hpp"
#include "predicates/bisector.hpp"
#include "predicates/distortion.hpp"
#include "predicates/encroachment.hpp"
#include "predicates/incircle.hpp"
#include "predicates/length_compare.hpp"
#include "predicates/metric.hpp"
#include "predicates/orientation.hpp"
#include "predicates/sqrt_sign.hpp"
#include "predicates/wedge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::Sign;
using anisocert::FilterInterval;

namespace {

template <class K>
std::array<Rational, K::arity> exact_inputs(const std::array<double, K::arity>& x) {
  std::array<Rational, K::arity> q;
  for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
  return q;
}

// The double path, the rational path and the plain exact evaluation agree; returns the sign.
template <class K>
Sign checked(const std::array<double, K::arity>& x) {
  const auto q = exact_inputs<K>(x);
  const Sign exact = exact_sign<K>(q);
  EXPECT_EQ(filtered_sign<K>(x), exact) << K::name;
  EXPECT_EQ(filtered_sign<K>(q), exact) << K::name;
  return exact;
}

struct Random {
  std::mt19937_64 rng{20261122};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  // A coordinate of magnitude about 2^e, e in [−70, 70]: inside and outside the static range.
  double coordinate(int e) { return std::ldexp(uniform(-1, 1), e); }
  // A symmetric positive definite metric with entries about 2^e.
  std::array<double, 3> metric(int e) {
    const double a = std::ldexp(uniform(0.1, 1), e), c = std::ldexp(uniform(0.1, 1), e);
    return {a, uniform(-0.99, 0.99) * std::sqrt(a * c), c};
  }
  template <std::size_t N>
  std::array<double, N> inputs(const std::array<int, N>& groups) {
    const int ec = integer(-70, 70), em = integer(-70, 70), es = integer(-70, 70);
    std::array<double, N> x{};
    for (std::size_t i = 0; i < N; ++i) {
      if (groups[i] == 0) x[i] = coordinate(ec);
      if (groups[i] == 2) x[i] = std::ldexp(uniform(0, 1), es);
    }
    // Metric entries come in (m11, m12, m22) triples, except the single entries of the
    // distortion's diagonal kernel.
    for (std::size_t i = 0; i < N; ++i)
      if (groups[i] == 1 && x[i] == 0) {
        if (i + 2 < N && groups[i + 1] == 1 && groups[i + 2] == 1) {
          auto m = metric(em);
          x[i] = m[0], x[i + 1] = m[1], x[i + 2] = m[2];
          i += 2;
        } else {
          x[i] = std::ldexp(uniform(0.1, 1), em);
        }
      }
    return x;
  }
  // Moves one input by 1..4 ulps.
  template <std::size_t N>
  std::array<double, N> nudged(std::array<double, N> x) {
    const std::size_t i = static_cast<std::size_t>(integer(0, N - 1));
    const double toward = integer(0, 1) ? INFINITY : -INFINITY;
    for (int k = integer(1, 4); k > 0; --k) x[i] = std::nextafter(x[i], toward);
    return x;
  }
};

// F unimodular (det 1): F⁻¹ is an integer matrix, so points c + F⁻¹·(integer vector of
// length 5) are integers, exactly on the M-circle of radius 5 around c for M = FᵀF.
struct Unimodular {
  long f11, f12, f21, f22;  // det = f11 f22 − f12 f21 = 1
  std::array<double, 3> metric() const {
    return {double(f11 * f11 + f21 * f21), double(f11 * f12 + f21 * f22), double(f12 * f12 + f22 * f22)};
  }
  // c + F⁻¹ (x, y), F⁻¹ = [f22 −f12; −f21 f11]
  std::array<double, 2> at(std::array<double, 2> c, long x, long y) const {
    return {c[0] + double(f22 * x - f12 * y), c[1] + double(-f21 * x + f11 * y)};
  }
};
const Unimodular shears[] = {{1, 0, 0, 1}, {1, 1, 0, 1}, {2, 1, 1, 1}, {1, -3, 0, 1}, {3, 2, 4, 3}, {5, 7, 2, 3}};
const long circle5[][2] = {{5, 0}, {3, 4}, {0, 5}, {-4, 3}, {-5, 0}, {-3, -4}, {4, -3}, {0, -5}};

}  // namespace

TEST(FilteredVsExact, RandomInputsAcrossMagnitudes) {
  Random r;
  for (int t = 0; t < 3000; ++t) {
    checked<OrientationKernel>(r.inputs(OrientationKernel::groups));
    checked<SideOfBisectorKernel>(r.inputs(SideOfBisectorKernel::groups));
    checked<MetricDotKernel>(r.inputs(MetricDotKernel::groups));
    checked<InCircleKernel>(r.inputs(InCircleKernel::groups));
    checked<ScaledLengthCompareKernel>(r.inputs(ScaledLengthCompareKernel::groups));
    checked<AngleCosKernel>(r.inputs(AngleCosKernel::groups));
    checked<AngleSinKernel>(r.inputs(AngleSinKernel::groups));
    checked<ScaledDifferenceDiagonalKernel>(r.inputs(ScaledDifferenceDiagonalKernel::groups));
    checked<ScaledDifferenceDeterminantKernel>(r.inputs(ScaledDifferenceDeterminantKernel::groups));
  }
}

// The orientation's axis-parallel shortcut (an edge ab with a.x = b.x or a.y = b.y decided from
// the signs of two differences) against the exact kernel: across magnitudes, with c on the line,
// a few ulps off it, on either side, a = b, and far apart in magnitude (differences that round).
TEST(FilteredVsExact, OrientationOfAxisParallelEdges) {
  Random r;
  int zeros = 0, nonzeros = 0;
  for (int t = 0; t < 4000; ++t) {
    const int e = r.integer(-70, 70), f = r.integer(-70, 70);
    const double x = r.coordinate(e), y0 = r.coordinate(e), y1 = t % 17 == 0 ? y0 : r.coordinate(f);
    double cx = t % 3 == 0 ? x : r.coordinate(r.integer(-70, 70));
    if (t % 3 == 1) for (int k = r.integer(1, 3); k > 0; --k) cx = std::nextafter(cx, t % 2 ? INFINITY : -INFINITY);
    const double cy = r.coordinate(f);
    const bool vertical = t % 2 == 0;
    const Point2<double> a = vertical ? Point2<double>{x, y0} : Point2<double>{y0, x};
    const Point2<double> b = vertical ? Point2<double>{x, y1} : Point2<double>{y1, x};
    const Point2<double> c = vertical ? Point2<double>{cx, cy} : Point2<double>{cy, cx};
    const std::array<double, 6> in{a.x, a.y, b.x, b.y, c.x, c.y};
    const Sign exact = exact_sign<OrientationKernel>(exact_inputs<OrientationKernel>(in));
    EXPECT_EQ(orientation(a, b, c), exact) << t;
    EXPECT_EQ(orientation(Point2<Rational>{a.x, a.y}, Point2<Rational>{b.x, b.y}, Point2<Rational>{c.x, c.y}), exact) << t;
    (exact == Sign::zero ? zeros : nonzeros) += 1;
  }
  EXPECT_GT(zeros, 500);
  EXPECT_GT(nonzeros, 2000);
}

TEST(FilteredVsExact, ExactlyDegenerateAndNearlyDegenerate) {
  Random r;
  int zeros = 0;
  for (int t = 0; t < 400; ++t) {
    const Unimodular& F = shears[t % 6];
    const Unimodular& G = shears[(t / 6) % 6];
    const std::array<double, 2> c{double(r.integer(-1000, 1000)), double(r.integer(-1000, 1000))};
    const long k = r.integer(1, 50);
    const auto* p1 = circle5[r.integer(0, 7)];
    const auto* p2 = circle5[r.integer(0, 7)];
    const auto a = F.at(c, k * p1[0], k * p1[1]), b = G.at(c, k * p2[0], k * p2[1]);
    const auto M = F.metric(), N = G.metric();
    std::vector<std::pair<const char*, Sign>> results;
    // Collinear: c, a, and c + 3(a − c).
    const std::array<double, 6> collinear{c[0], c[1], a[0], a[1], c[0] + 3 * (a[0] - c[0]), c[1] + 3 * (a[1] - c[1])};
    // c is on the bisector of a (metric M) and b (metric N): d_M(a, c) = d_N(b, c) = 5k.
    const std::array<double, 12> bisector{c[0], c[1], a[0], a[1], M[0], M[1], M[2], b[0], b[1], N[0], N[1], N[2]};
    // On a wedge line: q = a + s·J·M(b − a), J the quarter turn, so (q − a)ᵀM(b − a) = 0.
    const double gx = M[0] * (b[0] - a[0]) + M[1] * (b[1] - a[1]), gy = M[1] * (b[0] - a[0]) + M[2] * (b[1] - a[1]);
    const std::array<double, 9> wedge_line{a[0] - gy, a[1] + gx, a[0], a[1], b[0], b[1], M[0], M[1], M[2]};
    // Four points on one M-circle around c.
    std::array<double, 8> circle{};
    for (int i = 0; i < 4; ++i) {
      const auto p = F.at(c, k * circle5[2 * i][0], k * circle5[2 * i][1]);
      circle[2 * i] = p[0], circle[2 * i + 1] = p[1];
    }
    const std::array<double, 11> cocircular{circle[0], circle[1], circle[2], circle[3], circle[4], circle[5],
                                            circle[6], circle[7], M[0], M[1], M[2]};
    // On the diametral M-circle of the segment from c + F⁻¹(5k, 0) to c − F⁻¹(5k, 0).
    const auto e1 = F.at(c, 5 * k, 0), e2 = F.at(c, -5 * k, 0), on = F.at(c, 3 * k, 4 * k);
    const std::array<double, 9> diametral{e1[0], e1[1], on[0], on[1], e2[0], e2[1], M[0], M[1], M[2]};
    // Equal lengths: d_M(c, a)² = 1 · d_M(c, F.at(c, 0, 5k))².
    const auto a2 = F.at(c, 0, 5 * k);
    const std::array<double, 15> equal_lengths{1,    c[0], c[1], a[0], a[1], M[0], M[1], M[2],
                                               c[0], c[1], a2[0], a2[1], M[0], M[1], M[2]};
    // A right angle at c measured by M: cos = 0 against k = 0, and sin² = 1.
    const auto right = F.at(c, 0, 5 * k), base = F.at(c, 5 * k, 0);
    const std::array<double, 10> right_cos{base[0], base[1], c[0], c[1], right[0], right[1], M[0], M[1], M[2], 0};
    const std::array<double, 10> right_sin{base[0], base[1], c[0], c[1], right[0], right[1], M[0], M[1], M[2], 1};
    // Equal metrics, γ² = 1: g·P − Q = 0; and g·p11 = q11 with g = 2.
    const std::array<double, 7> equal_metrics{1, M[0], M[1], M[2], M[0], M[1], M[2]};
    const std::array<double, 3> equal_diagonal{2, M[0], 2 * M[0]};

    zeros += checked<OrientationKernel>(collinear) == Sign::zero;
    zeros += checked<SideOfBisectorKernel>(bisector) == Sign::zero;
    zeros += checked<MetricDotKernel>(wedge_line) == Sign::zero;
    zeros += checked<InCircleKernel>(cocircular) == Sign::zero;
    zeros += checked<MetricDotKernel>(diametral) == Sign::zero;
    zeros += checked<ScaledLengthCompareKernel>(equal_lengths) == Sign::zero;
    zeros += checked<AngleCosKernel>(right_cos) == Sign::zero;
    zeros += checked<AngleSinKernel>(right_sin) == Sign::zero;
    zeros += checked<ScaledDifferenceDeterminantKernel>(equal_metrics) == Sign::zero;
    zeros += checked<ScaledDifferenceDiagonalKernel>(equal_diagonal) == Sign::zero;
    for (int n = 0; n < 3; ++n) {
      checked<ScaledDifferenceDiagonalKernel>(r.nudged(equal_diagonal));
      checked<OrientationKernel>(r.nudged(collinear));
      checked<SideOfBisectorKernel>(r.nudged(bisector));
      checked<MetricDotKernel>(r.nudged(wedge_line));
      checked<InCircleKernel>(r.nudged(cocircular));
      checked<MetricDotKernel>(r.nudged(diametral));
      checked<ScaledLengthCompareKernel>(r.nudged(equal_lengths));
      checked<AngleCosKernel>(r.nudged(right_cos));
      checked<AngleSinKernel>(r.nudged(right_sin));
      checked<ScaledDifferenceDeterminantKernel>(r.nudged(equal_metrics));
    }
  }
  EXPECT_EQ(zeros, 400 * 10);  // every constructed degeneracy is exactly degenerate
}

TEST(FilteredVsExact, SmallClustersFarFromTheOrigin) {
  // The translated static stage (orientation, in-circle) works on rounded differences: exactly
  // degenerate clusters 2⁻ˢ small at offsets up to 2³⁰, and the same a few ulps off. Every point
  // is B + 2⁻ˢ·(integer), exact in doubles because B has few bits.
  Random r;
  int zeros = 0;
  for (int t = 0; t < 2000; ++t) {
    const Unimodular& F = shears[t % 6];
    const int s = r.integer(0, 20), m = r.integer(0, 20);
    const std::array<double, 2> B{std::ldexp(r.integer(-1000, 1000), m), std::ldexp(r.integer(-1000, 1000), m)};
    const long k = r.integer(1, 50);
    auto at = [&](long x, long y) {
      const auto p = F.at({0, 0}, x, y);
      return std::array<double, 2>{B[0] + std::ldexp(p[0], -s), B[1] + std::ldexp(p[1], -s)};
    };
    const auto M = F.metric();
    std::array<double, 8> circle{};
    for (int i = 0; i < 4; ++i) {
      const auto p = at(k * circle5[2 * i][0], k * circle5[2 * i][1]);
      circle[2 * i] = p[0], circle[2 * i + 1] = p[1];
    }
    const std::array<double, 11> cocircular{circle[0], circle[1], circle[2], circle[3], circle[4], circle[5],
                                            circle[6], circle[7], M[0], M[1], M[2]};
    const auto a = at(k * 3, k * 4), b = at(k * 6, k * 8), c = at(k * 9, k * 12);
    const std::array<double, 6> collinear{a[0], a[1], b[0], b[1], c[0], c[1]};
    zeros += checked<InCircleKernel>(cocircular) == Sign::zero;
    zeros += checked<OrientationKernel>(collinear) == Sign::zero;
    for (int n = 0; n < 4; ++n) {
      checked<InCircleKernel>(r.nudged(cocircular));
      checked<OrientationKernel>(r.nudged(collinear));
    }
  }
  EXPECT_EQ(zeros, 2000 * 2);
}

TEST(FilteredVsExact, StaticFilterDecidesSmallClusters) {
  // Points 2⁻²⁰ apart near (0.7, 0.3), as in a fine mesh: the untranslated bound, taken over the
  // coordinates' magnitude, is about (0.7·2²⁰)⁴ times the in-circle's value and could not decide
  // one; the translated stage must decide nearly all.
  Random r;
  filter_stats() = {};
  for (int t = 0; t < 10000; ++t) {
    std::array<double, 11> x{};
    for (int i = 0; i < 8; ++i) x[i] = (i % 2 ? 0.3 : 0.7) + std::ldexp(r.uniform(-1, 1), -20);
    const auto m = r.metric(0);
    x[8] = m[0], x[9] = m[1], x[10] = m[2];
    filtered_sign<InCircleKernel>(x);
    filtered_sign<OrientationKernel>(std::array<double, 6>{x[0], x[1], x[2], x[3], x[4], x[5]});
  }
  EXPECT_LT(filter_stats().interval_stage, 200u);  // < 1% of 20000
}

TEST(FilteredVsExact, MixedMagnitudesAndTheEdgesOfTheStaticRange) {
  // Review finding: exercise the underflow allowance (tiny coordinates beside a group max of
  // about 1), group maxima exactly at 2^±50 and just outside, and subnormal inputs.
  Random r;
  const double edges[] = {0x1p50, 0x1p-50, std::nextafter(0x1p50, INFINITY), std::nextafter(0x1p-50, 0.0), 1.0};
  for (int t = 0; t < 3000; ++t) {
    std::array<double, 11> x = r.inputs(InCircleKernel::groups);
    std::array<double, 12> y = r.inputs(SideOfBisectorKernel::groups);
    for (std::size_t i = 0; i < 8; ++i)  // some coordinates tiny, even subnormal
      if (r.integer(0, 2) == 0) x[i] = std::ldexp(r.uniform(-1, 1), r.integer(-1074, -300));
    x[r.integer(0, 7)] = edges[r.integer(0, 4)] * (r.integer(0, 1) ? 1 : -1);
    y[r.integer(0, 3)] = std::ldexp(r.uniform(-1, 1), r.integer(-1074, -900));
    y[4] = edges[r.integer(0, 4)];
    checked<InCircleKernel>(x);
    checked<SideOfBisectorKernel>(y);
    // Points nearly coincident at tiny scale: differences are subnormal, products underflow.
    const double base = std::ldexp(1.0, r.integer(-1074, -1000));
    checked<OrientationKernel>({base, 0, 2 * base, base, 3 * base, std::nextafter(2 * base, 1.0)});
  }
}

TEST(FilterInterval, EnclosesRationalsBeyondTheDoubleRange) {
  using anisocert::Integer;
  const Integer big = boost::multiprecision::pow(Integer{10}, 400);
  for (const Rational& q : {Rational(big), Rational(-big), Rational(1) / Rational(big), Rational(-1) / Rational(big),
                            Rational(3) / Rational(boost::multiprecision::pow(Integer{2}, 1075)),
                            Rational(1, 3), Rational(0)}) {
    const FilterInterval i = FilterInterval::around(q);
    EXPECT_TRUE(std::isinf(i.lo) || Rational(i.lo) <= q) << q;
    EXPECT_TRUE(std::isinf(i.hi) || Rational(i.hi) >= q) << q;
    if (std::isinf(i.lo)) {
      EXPECT_LT(i.lo, 0);
    }
    if (std::isinf(i.hi)) {
      EXPECT_GT(i.hi, 0);
    }
  }
}

TEST(BadInput, EarlyDecisionsStillRejectNonFiniteInputs) {
  // Review finding: a wrapper that decides from its first kernel must not answer for a NaN in
  // an input it did not read yet.
  const Point2<double> a{1, 0}, b{0, 0}, c{1, 1}, o{-1, 0.5};
  const Sym2<double> I{1, 0, 1};
  EXPECT_THROW(compare_angle_cos(a, b, c, I, double(NAN)), NonFiniteInput);
  EXPECT_THROW(angle_at_least_arcsin(o, b, a, I, double(NAN)), NonFiniteInput);  // obtuse: sin2 unread
  EXPECT_THROW(radius_edge_at_most(0.1, b, {a, Point2<double>{0, 1}, Point2<double>{NAN, 0}}, {I, I, I}),
               NonFiniteInput);
  EXPECT_THROW(tau_at_most(Sym2<double>{1, 0, 1}, Sym2<double>{4, NAN, 1}, 1.0), NonFiniteInput);
  // Review finding: orientation's shortcut for points on one axis-parallel line (x = +∞ thrice,
  // or a NaN in the other coordinate) must not answer "collinear".
  EXPECT_THROW(orientation(Point2<double>{INFINITY, 0}, Point2<double>{INFINITY, 1}, Point2<double>{INFINITY, 2}), NonFiniteInput);
  EXPECT_THROW(orientation(Point2<double>{1, NAN}, Point2<double>{1, 0}, Point2<double>{1, 2}), NonFiniteInput);
  // τ of matrices that are not positive definite is refused, not answered.
  EXPECT_THROW(compare_tau_squared(Sym2<Rational>{0, 0, 0}, Sym2<Rational>{1, 0, 1}, Rational(2)), NotPositiveDefinite);
  EXPECT_THROW(compare_tau(Sym2<Rational>{1, 0, -1}, Sym2<Rational>{1, 0, 1}, Sym2<Rational>{1, 0, 1},
                           Sym2<Rational>{1, 0, 1}),
               NotPositiveDefinite);
}

TEST(FilteredVsExact, StaticFilterDecidesRandomInputs) {
  // A filter that always fell through would be correct but useless: on random inputs in the
  // static range, the static stage must decide nearly every call.
  Random r;
  filter_stats() = {};
  for (int t = 0; t < 10000; ++t) {
    std::array<double, 12> x{};
    for (std::size_t i = 0; i < 12; ++i) x[i] = r.uniform(-1, 1);
    auto m1 = r.metric(0), m2 = r.metric(0);
    x[4] = m1[0], x[5] = m1[1], x[6] = m1[2], x[9] = m2[0], x[10] = m2[1], x[11] = m2[2];
    filtered_sign<SideOfBisectorKernel>(x);
  }
  EXPECT_LT(filter_stats().interval_stage, 100u);  // < 1%
}

// Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems in
// geometric computations": orientation(p, q, r) for p = (0.5 + x·2⁻⁵³, 0.5 + y·2⁻⁵³),
// q = (12, 12), r = (24, 24). Exactly: (12 − px)(24 − py) − (12 − py)(24 − px) = 12(y − x)·2⁻⁵³
// (expand, the products cancel), so the expected sign is sign(y − x): a closed form.
TEST(ClassroomExamples, OrientationGridOf256x256) {
  int naive_wrong = 0;
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) {
      const Point2<double> p{0.5 + std::ldexp(x, -53), 0.5 + std::ldexp(y, -53)}, q{12, 12}, r{24, 24};
      const Sign expected = y > x ? Sign::positive : y < x ? Sign::negative : Sign::zero;
      ASSERT_EQ(orientation(p, q, r), expected) << x << "," << y;
      const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
      naive_wrong += (naive > 0 ? Sign::positive : naive < 0 ? Sign::negative : Sign::zero) != expected;
    }
  EXPECT_GT(naive_wrong, 0);  // the fixture does defeat plain double evaluation
}

TEST(AngleAgainstBound, AgreesWithTheSquareRootForm) {
  // sign(cos θ − k) = sign(uᵀMw − k·√(uᵀMu · wᵀMw)), evaluated by sign_of_root_sum.
  Random r;
  for (int t = 0; t < 2000; ++t) {
    const Point2<Rational> a{r.integer(-9, 9), r.integer(-9, 9)}, b{r.integer(-9, 9), r.integer(-9, 9)},
        c{r.integer(-9, 9), r.integer(-9, 9)};
    if ((a.x == b.x && a.y == b.y) || (c.x == b.x && c.y == b.y)) continue;
    const Sym2<Rational> M{r.integer(1, 9), r.integer(-2, 2), r.integer(1, 9)};
    if (M.m11 * M.m22 <= M.m12 * M.m12) continue;  // positive definite metrics only
    const Rational k(r.integer(-5, 5), 5);  // includes cos = ±1, 0, 3/5, 4/5 exactly
    const Rational dot = bilinear_form(M.m11, M.m12, M.m22, a.x - b.x, a.y - b.y, c.x - b.x, c.y - b.y);
    const Rational uu = quadratic_form(M.m11, M.m12, M.m22, a.x - b.x, a.y - b.y);
    const Rational ww = quadratic_form(M.m11, M.m12, M.m22, c.x - b.x, c.y - b.y);
    EXPECT_EQ(compare_angle_cos(a, b, c, M, k), sign_of_root_sum(dot, -k, uu * ww));
    // θ >= arcsin s ⇔ θ >= 90° or sin²θ >= s², sin²θ = 1 − dot²/(uu ww).
    const Rational s2 = k * k;
    EXPECT_EQ(angle_at_least_arcsin(a, b, c, M, s2), dot <= 0 || uu * ww - dot * dot >= s2 * uu * ww);
  }
}

TEST(Encroachment, DiametralCircleOfTheMetric) {
  // M = diag(4, 1): the diametral M-circle of a = (−1, 0), b = (1, 0) is 4x² + y² = 4 (centre 0,
  // M-radius 2), so (0, 2) is on it, (0, 1) inside, (0, 3) and (1, 1) outside: (a − p)ᵀM(b − p).
  const Sym2<Rational> M{4, 0, 1};
  const Point2<Rational> a{-1, 0}, b{1, 0};
  EXPECT_FALSE(encroaches(Point2<Rational>{0, 2}, a, b, M));  // (−1,−2)M(1,−2) = −4 + 4 = 0
  EXPECT_TRUE(encroaches(Point2<Rational>{0, 1}, a, b, M));   // −4 + 1 < 0
  EXPECT_FALSE(encroaches(Point2<Rational>{0, 3}, a, b, M));  // −4 + 9 > 0
  EXPECT_FALSE(encroaches(Point2<Rational>{1, 1}, a, b, M));  // (−2,−1)M(0,−1) = 1 > 0
}

TEST(RadiusEdge, RightIsoscelesTriangleHasRatioOneOverSqrt2) {
  // q = 0, v = (1, 0), (0, 1), (−1, 0) with M = I: r = 1, ℓ = √2, r/ℓ = 1/√2: B² = 1/2 exactly.
  const Sym2<Rational> I{1, 0, 1};
  const std::array<Point2<Rational>, 3> v{Point2<Rational>{1, 0}, Point2<Rational>{0, 1}, Point2<Rational>{-1, 0}};
  const Point2<Rational> q{0, 0};
  EXPECT_TRUE(radius_edge_at_most(Rational(1, 2), q, v, {I, I, I}));
  EXPECT_FALSE(radius_edge_at_most(Rational(1, 2) - Rational(1, 1000000000), q, v, {I, I, I}));
  // The same with doubles (0.5 is exact).
  const Sym2<double> Id{1, 0, 1};
  const std::array<Point2<double>, 3> vd{Point2<double>{1, 0}, Point2<double>{0, 1}, Point2<double>{-1, 0}};
  EXPECT_TRUE(radius_edge_at_most(0.5, Point2<double>{0, 0}, vd, {Id, Id, Id}));
  EXPECT_FALSE(radius_edge_at_most(std::nextafter(0.5, 0.0), Point2<double>{0, 0}, vd, {Id, Id, Id}));
}

TEST(SqrtSign, HandCheckedCases) {
  // 1 + √2 − √5 = 1 + 1.41421 − 2.23607 > 0; 3 − √2 − √3 < 0 (3 − 3.146); 2√2 − √8 = 0.
  EXPECT_EQ(sign_of_root_sum(1, 1, 2, -1, 5), Sign::positive);
  EXPECT_EQ(sign_of_root_sum(3, -1, 2, -1, 3), Sign::negative);
  EXPECT_EQ(sign_of_root_sum(0, 2, 2, -1, 8), Sign::zero);
  EXPECT_EQ(sign_of_root_sum(-3, 1, 9), Sign::zero);
  EXPECT_EQ(sign_of_root_sum(5, -2, 6), Sign::positive);  // 25 > 24
  EXPECT_EQ(sign_of_root_sum(5, 1, 0, -1, 25), Sign::zero);
  // Two terms of the same sign and equal magnitude add up, they do not cancel: √2 + √2 > 0,
  // −1 − √1 < 0 (a mutant that compared magnitudes here answered 0).
  EXPECT_EQ(sign_of_root_sum(0, 1, 2, 1, 2), Sign::positive);
  EXPECT_EQ(sign_of_root_sum(-1, 0, 0, -1, 1), Sign::negative);
  // Opposite signs where a² − b² = 3 − 6 + 2√2 hangs on the cross term 2xy√X: 1 + √2 − √6 =
  // 2.41421 − 2.44949 < 0 (a version with 3xy there answered positive: the 2026-12-02 campaign).
  EXPECT_EQ(sign_of_root_sum(1, 1, 2, -1, 6), Sign::negative);
  EXPECT_EQ(sign_of_root_sum(-1, -1, 2, 1, 6), Sign::positive);
  // A negative radicand is no real number: refused, in either place.
  EXPECT_THROW(sign_of_root_sum(1, 1, -2), std::domain_error);
  EXPECT_THROW(sign_of_root_sum(1, 1, 2, 1, -3), std::domain_error);
}

TEST(BadInput, NonFiniteInputsAreNamed) {
  const Point2<double> a{0, 0}, b{1, NAN}, c{2, 2};
  try {
    orientation(a, b, c);
    FAIL();
  } catch (const NonFiniteInput& e) {
    // The predicate, then the input by name, then its value: the whole prefix, in that order.
    EXPECT_EQ(std::string(e.what()).rfind("orientation: input b.y = nan", 0), 0u) << e.what();
  }
  const Sym2<double> M{1, 0, INFINITY};
  EXPECT_THROW(side_of_bisector(a, c, M, b, M), NonFiniteInput);
}
