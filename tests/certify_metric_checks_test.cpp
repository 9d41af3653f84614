// The metric checks of the certifier (oracle/certify/metric_checks.hpp) on meshes with closed-form
// answers: an equilateral unit mesh in a constant metric M = FᵀF, mapped by F⁻¹, has every edge of
// length exactly 1, every mean ratio exactly 1 and every angle exactly 60°.
//
// No √3 is needed: the equilateral lattice's basis e₁, e₂ (unit, at 60°) has the rational Gram
// matrix G = [[1, 1/2], [1/2, 1]], so the lattice point (i, j) is the rational point (i, j) in the
// metric G, and p = A⁻¹(i, j) in M = AᵀGA for any rational invertible A: (Δp)ᵀ M Δp = (Δi, Δj) G
// (Δi, Δj)ᵀ = 1 for lattice neighbours (Δ = (1, 0), (0, 1), (1, −1)). The same metric gives a
// 30°–60°–90° triangle ((0, 0), (1, 0), (1/2, 1/2) in G), and M = AᵀA gives 45°–45°–90°. Ties at the
// bound are the point: each bound is tested at the closed-form value (holds), just past it (fails on
// every edge or triangle) and just before it.
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/certify/metric_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using anisocert::Rational;
using anisocert::FilterInterval;
using namespace anisocert::oracle;
using P = anisocert::predicates::Point2<Rational>;
using Sym = anisocert::predicates::Sym2<Rational>;

// A = [[a11, a12], [a21, a22]]
struct Matrix {
  Rational a11, a12, a21, a22;
  Rational det() const { return a11 * a22 - a12 * a21; }
  P inverse_times(const Rational& x, const Rational& y) const {  // A⁻¹ (x, y)
    return {(a22 * x - a12 * y) / det(), (a11 * y - a21 * x) / det()};
  }
  // AᵀSA for the symmetric S = [[s11, s12], [s12, s22]]
  Sym congruent(const Sym& s) const {
    const Rational b11 = s.m11 * a11 + s.m12 * a21, b12 = s.m11 * a12 + s.m12 * a22;  // S A, first row
    const Rational b21 = s.m12 * a11 + s.m22 * a21, b22 = s.m12 * a12 + s.m22 * a22;  // second row
    return {a11 * b11 + a21 * b21, a11 * b12 + a21 * b22, a12 * b12 + a22 * b22};
  }
};

const Sym gram{1, Rational(1, 2), 1};  // the equilateral lattice's Gram matrix
const Sym identity{1, 0, 1};
const Matrix frame{Rational(3, 2), Rational(-1, 3), Rational(2, 5), Rational(7, 10)};  // det 71/60 > 0
const Matrix decimal_frame{Rational(1, 10), Rational(3, 10), Rational(-7, 10), Rational(11, 100)};

Rational ten_to_minus(int k) {
  Rational r = 1;
  for (int i = 0; i < k; ++i) r /= 10;
  return r;
}

// The (n + 1)² lattice points (i, j) mapped by A⁻¹, the 2n² lattice triangles (counter-clockwise
// in lattice coordinates, so in the plane too since det A > 0), metric AᵀGA at every site.
Mesh<Rational> equilateral_patch(const Matrix& A, int n) {
  Mesh<Rational> m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.sites.push_back(A.inverse_times(i, j));
  m.metrics.assign(m.sites.size(), A.congruent(gram));
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Every edge once, (a, b) with a < b, written out from the triangles here.
std::vector<std::pair<int, int>> edges_of(const Mesh<Rational>& m) {
  std::vector<std::pair<int, int>> e;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) e.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

TEST(MetricChecks, EquilateralUnitMeshHasEveryEdgeOfLengthExactlyOne) {
  for (const Matrix& A : {frame, decimal_frame}) {
    const Mesh<Rational> m = equilateral_patch(A, 3);
    const EnclosedMesh em(m);
    const auto edges = edges_of(m);
    ASSERT_EQ(edges.size(), 3u * 3 * 3 + 2 * 3);  // 3n² + 2n
    const LengthReport all = check_lengths(em, edges, std::nullopt);
    EXPECT_EQ(all.edges, edges.size());
    EXPECT_EQ(all.unit_edges, edges.size());  // unit share 100%
    ASSERT_EQ(all.lengths.size(), 2 * edges.size());
    for (double l : all.lengths) EXPECT_NEAR(l, 1.0, 1e-12);
    EXPECT_NEAR(all.shortest, 1.0, 1e-12);
    EXPECT_NEAR(all.longest, 1.0, 1e-12);
    EXPECT_TRUE(all.range_violations.empty());
    // [1, 1] holds: every length is exactly 1.
    EXPECT_TRUE(check_lengths(em, edges, std::pair(Rational(1), Rational(1))).range_violations.empty());
    // Just above or just below 1 at either end fails on every edge.
    for (const auto& range : {std::pair(Rational(1, 2), Rational(99, 100)), std::pair(Rational(101, 100), Rational(2)),
                              std::pair(Rational(1) + ten_to_minus(30), Rational(2)),
                              std::pair(Rational(0), Rational(1) - ten_to_minus(30))}) {
      const LengthReport r = check_lengths(em, edges, range);
      EXPECT_EQ(r.range_violations.count(), edges.size()) << "range [" << range.first << ", " << range.second << "]";
      EXPECT_EQ(r.unit_edges, edges.size());
    }
  }
}

TEST(MetricChecks, EquilateralUnitMeshHasMeanRatioExactlyOne) {
  for (const Matrix& A : {frame, decimal_frame}) {
    Mesh<Rational> m = equilateral_patch(A, 3);
    // The mean ratio does not change when a vertex's metric is scaled: scale some of them.
    for (std::size_t v = 0; v < m.metrics.size(); v += 3)
      m.metrics[v] = {m.metrics[v].m11 * 9 / 4, m.metrics[v].m12 * 9 / 4, m.metrics[v].m22 * 9 / 4};
    const EnclosedMesh em(m);
    const QualityReport one = check_quality(em, Rational(1));
    EXPECT_EQ(one.measured, m.triangles.size());
    EXPECT_EQ(one.undecided, 0u);
    EXPECT_TRUE(one.violations.empty());  // q >= 1 holds: the tie is exact
    EXPECT_LE(one.worst.lo, 1.0);
    EXPECT_GE(one.worst.hi, 1.0);
    EXPECT_LT(one.worst.hi - one.worst.lo, 1e-12);
    for (double q : one.qualities) EXPECT_NEAR(q, 1.0, 1e-12);
    for (const auto& [p, enclosure] : one.quantiles) {
      EXPECT_LE(enclosure.lo, 1.0) << p;
      EXPECT_GE(enclosure.hi, 1.0) << p;
    }
    EXPECT_TRUE(check_quality(em, Rational(999, 1000)).violations.empty());
    EXPECT_TRUE(check_quality(em, Rational(1) - ten_to_minus(40)).violations.empty());
    // Above 1 (no mesh reaches it): every triangle is a violation, one witness each.
    const QualityReport above = check_quality(em, Rational(1) + ten_to_minus(40));
    ASSERT_EQ(above.violations.count(), m.triangles.size());
    for (std::size_t t = 0; t < above.violations.count(); ++t) EXPECT_EQ(above.violations.described()[t].triangle, static_cast<int>(t));
  }
}

TEST(MetricChecks, EquilateralUnitMeshHasEveryAngleExactlySixtyDegrees) {
  for (const Matrix& A : {frame, decimal_frame}) {
    Mesh<Rational> m = equilateral_patch(A, 3);
    for (std::size_t v = 1; v < m.metrics.size(); v += 2)  // angles do not change with the scale either
      m.metrics[v] = {m.metrics[v].m11 / 7, m.metrics[v].m12 / 7, m.metrics[v].m22 / 7};
    const EnclosedMesh em(m);
    const std::size_t T = m.triangles.size();
    const AngleReport sixty = check_angles(em, Rational(60));
    EXPECT_EQ(sixty.measured, T);
    EXPECT_EQ(sixty.undecided, 0u);
    EXPECT_TRUE(sixty.violations.empty());  // sin² 60° = 3/4 exactly: the tie holds
    EXPECT_TRUE(sixty.undecided_triangles.empty());
    EXPECT_NEAR(sixty.smallest, 60.0, 1e-9);
    EXPECT_TRUE(check_angles(em, Rational(59)).violations.empty());
    // 60° − 10⁻²⁰ and 60° + 10⁻²⁰ are not among the exact values: the MPFI bounds must decide them.
    EXPECT_TRUE(check_angles(em, Rational(60) - ten_to_minus(20)).violations.empty());
    for (const Rational& theta : {Rational(61), Rational(60) + ten_to_minus(20), Rational(90)}) {
      const AngleReport r = check_angles(em, theta);
      EXPECT_EQ(r.violations.count(), T) << "θ = " << theta;  // every triangle, one witness each
      EXPECT_TRUE(r.undecided_triangles.empty());
    }
  }
}

// A 30°–60°–90° triangle in the lattice metric: (0, 0), (1, 0), (1/2, 1/2) in G (cos² 30° = 3/4).
TEST(MetricChecks, ThirtySixtyNinetyTriangleTiesAtThirtyDegrees) {
  for (const Matrix& A : {frame, decimal_frame}) {
    Mesh<Rational> m;
    m.sites = {A.inverse_times(0, 0), A.inverse_times(1, 0), A.inverse_times(Rational(1, 2), Rational(1, 2))};
    m.metrics.assign(3, A.congruent(gram));
    m.triangles = {{0, 1, 2}};
    const EnclosedMesh em(m);
    EXPECT_NEAR(check_angles(em, std::nullopt).smallest, 30.0, 1e-9);
    EXPECT_TRUE(check_angles(em, Rational(30)).violations.empty());
    EXPECT_TRUE(check_angles(em, Rational(30) - ten_to_minus(20)).violations.empty());
    for (const Rational& theta : {Rational(31), Rational(30) + ten_to_minus(20)}) {
      const AngleReport r = check_angles(em, theta);
      ASSERT_EQ(r.violations.count(), 1u) << "θ = " << theta;
      EXPECT_EQ(r.violations.described()[0].vertex, 0);  // the 30° corner
    }
  }
}

// The right isosceles triangle in M = I and mapped by A⁻¹ in AᵀA: 45°, 45°, 90°. The tie at 45°
// (sin² = 1/2) is exact; 46° fails at a 45° corner and never at the right angle.
TEST(MetricChecks, RightIsoscelesTriangleHoldsAtFortyFiveAndFailsAtFortySix) {
  for (const Matrix& A : {Matrix{1, 0, 0, 1}, frame, decimal_frame}) {
    Mesh<Rational> m;
    m.sites = {A.inverse_times(0, 0), A.inverse_times(1, 0), A.inverse_times(0, 1)};
    m.metrics = {A.congruent(identity), A.congruent({3, 0, 3}), A.congruent({Rational(1, 5), 0, Rational(1, 5)})};
    m.triangles = {{0, 1, 2}};
    const EnclosedMesh em(m);
    EXPECT_NEAR(check_angles(em, std::nullopt).smallest, 45.0, 1e-9);
    EXPECT_TRUE(check_angles(em, Rational(45)).violations.empty());
    EXPECT_TRUE(check_angles(em, Rational(44)).violations.empty());
    EXPECT_TRUE(check_angles(em, Rational(45) - ten_to_minus(25)).violations.empty());
    for (const Rational& theta : {Rational(46), Rational(45) + ten_to_minus(25), Rational(90)}) {
      const AngleReport r = check_angles(em, theta);
      ASSERT_EQ(r.violations.count(), 1u) << "θ = " << theta;
      EXPECT_NE(r.violations.described()[0].vertex, 0) << "the right angle is never below the bound";
      EXPECT_EQ(r.violations.described()[0].triangle, 0);
    }
    // Its mean ratio: 4√3 (1/2) / (1 + 1 + 2) = √3/2 in every vertex metric (each a multiple of AᵀA).
    const QualityReport q = check_quality(em, std::nullopt);
    EXPECT_NEAR(q.worst.lo, std::sqrt(3.0) / 2, 1e-12);
    EXPECT_LE(q.worst.lo, std::sqrt(3.0L) / 2);
    EXPECT_TRUE(check_quality(em, Rational(866, 1000)).violations.empty());
    EXPECT_EQ(check_quality(em, Rational(867, 1000)).violations.count(), 1u);
  }
}

// The certifier with every metric option at the closed-form values holds, and fails just past each.
TEST(MetricChecks, CertifierHoldsAtTheClosedFormBoundsOfTheEquilateralMesh) {
  const Mesh<Rational> m = equilateral_patch(frame, 2);
  CertifyOptions o;
  o.metric = true;
  o.length_range = std::pair(Rational(1), Rational(1));
  o.min_quality = Rational(1);
  o.min_angle = Rational(60);
  const CertifyReport r = certify_mesh(m, o);
  ASSERT_TRUE(r.valid.has_value());
  EXPECT_TRUE(r.valid->is_triangulation);
  ASSERT_TRUE(r.lengths && r.quality && r.angles);
  EXPECT_EQ(r.lengths->unit_edges, r.lengths->edges);
  EXPECT_EQ(r.lengths->edges, 3u * 2 * 2 + 2 * 2);
  EXPECT_TRUE(r.holds(o));
  CertifyOptions past = o;
  past.min_angle = Rational(61);
  EXPECT_FALSE(certify_mesh(m, past).holds(past));
  past = o;
  past.length_range = std::pair(Rational(0), Rational(1) - ten_to_minus(30));
  EXPECT_FALSE(certify_mesh(m, past).holds(past));
  past = o;
  past.min_quality = Rational(1) + ten_to_minus(30);
  EXPECT_FALSE(certify_mesh(m, past).holds(past));
}

// sin² θ for θ = 10°, 20°: the bounds enclose the root of the exact cubic that sin² θ satisfies
// (from sin 3θ = 3 sin θ − 4 sin³ θ = 1/2, resp. √3/2, squared): f(lo) and f(hi) have opposite signs
// and the bracket is narrow around the root (the cubic's other roots, sin² 50° and sin² 70°, resp.
// sin² 40° and sin² 80°, are far).
Rational cubic_for_ten(const Rational& u) { return u * (6 - 8 * u) * (6 - 8 * u) - 1; }
Rational cubic_for_twenty(const Rational& u) { return u * (3 - 4 * u) * (3 - 4 * u) - Rational(3, 4); }

TEST(MetricChecks, SinSquaredBoundsEncloseTheClosedForms) {
  using Cubic = Rational (*)(const Rational&);
  const std::pair<int, Cubic> cubics[] = {{10, cubic_for_ten}, {20, cubic_for_twenty}};
  for (long prec : {64L, 128L, 512L}) {
    for (const auto& [deg, f] : cubics) {
      const auto [lo, hi] = sin_squared_bounds(Rational(deg), prec);
      EXPECT_LT(lo, hi) << deg << "° is irrational";
      EXPECT_LE(f(lo) * f(hi), 0) << deg << "° at precision " << prec;
      EXPECT_LT(hi - lo, Rational(1, 1000000));
    }
  }
  for (int deg : {10, 20, 89}) {
    const long double s = std::sin(static_cast<long double>(deg) * std::numbers::pi_v<long double> / 180);
    const long double s2 = s * s;
    const auto [lo, hi] = sin_squared_bounds(Rational(deg), 128);
    EXPECT_LT(lo, hi);
    EXPECT_LE(static_cast<long double>(lo.convert_to<double>()), s2 + 1e-15L) << deg;
    EXPECT_GE(static_cast<long double>(hi.convert_to<double>()), s2 - 1e-15L) << deg;
    EXPECT_LT(hi - lo, Rational(1, 1000000000) * Rational(1, 1000000000) * Rational(1, 1000000000)) << "128 bits";
  }
  // Exact, at any precision, for the four rational values (however the degrees are written).
  const std::pair<Rational, Rational> exact[] = {{Rational(30), Rational(1, 4)}, {Rational(90, 2), Rational(1, 2)},
                                                 {Rational(60), Rational(3, 4)}, {Rational(90), Rational(1)}};
  for (const auto& [deg, s2] : exact)
    for (long prec : {53L, 128L}) {
      const auto [lo, hi] = sin_squared_bounds(deg, prec);
      EXPECT_EQ(lo, s2) << deg;
      EXPECT_EQ(hi, s2) << deg;
    }
  // Just off an exact value: an enclosure that excludes it, on the right side.
  const auto [lo, hi] = sin_squared_bounds(Rational(60) + ten_to_minus(20), 256);
  EXPECT_GT(lo, Rational(3, 4));
  EXPECT_LT(lo, hi);
}

}  // namespace
