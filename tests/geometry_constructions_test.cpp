// geometry/: each construction is written once over the number type, so the double, interval and
// rational evaluations are the same code; these tests check each against an independent answer
// (a closed form, the defining equations decided exactly, a second method) and the evaluations
// against each other, on random inputs across magnitudes and shapes.
#include "geometry/circumellipse.hpp"
#include "geometry/distortion_estimate.hpp"
#include "geometry/ellipse_box.hpp"
#include "geometry/polygon.hpp"
#include "numbers/filter_interval.hpp"
#include "predicates/distortion.hpp"
#include "predicates/orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace anisocert;
using geometry::Polygon;
using predicates::Point2;
using predicates::Sym2;

// q in the closed interval; an infinite end (a divisor containing 0 gives the whole line) bounds nothing.
bool contains(const FilterInterval& i, const Rational& q) {
  return (i.lo == -INFINITY || Rational(i.lo) <= q) && (i.hi == INFINITY || q <= Rational(i.hi));
}
Point2<Rational> exact(const Point2<double>& p) { return {Rational(p.x), Rational(p.y)}; }
Sym2<Rational> exact(const Sym2<double>& m) { return {Rational(m.m11), Rational(m.m12), Rational(m.m22)}; }
Point2<FilterInterval> enclose(const Point2<double>& p) { return {p.x, p.y}; }
Sym2<FilterInterval> enclose(const Sym2<double>& m) { return {m.m11, m.m12, m.m22}; }

// A random metric: eigenvalues λ = 2^(−e)… with anisotropy up to 1:10⁴, random direction.
Sym2<double> random_metric(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double l1 = std::pow(10.0, 4 * u(rng) - 2), l2 = l1 * std::pow(10.0, 4 * u(rng) - 2), a = 3.14159 * u(rng);
  const double c = std::cos(a), s = std::sin(a);
  return {l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c};
}

// Closed forms: for M = FᵀF the circumellipse is F⁻¹ of the Euclidean circumcircle of F·points.
// M = diag(4, 1), F = diag(2, 1): (0, 0), (1, 0), (0, 2) map to (0, 0), (2, 0), (0, 2), whose
// circumcentre is (1, 1) with r² = 2; so the centre is (1/2, 1) and r² = 2.
TEST(Circumellipse, ClosedFormOfAStretchedRightTriangle) {
  const geometry::Circumellipse<Rational> c =
      geometry::circumellipse<Rational>({0, 0}, {1, 0}, {0, 2}, {4, 0, 1});
  EXPECT_EQ(c.cx, Rational(1, 2));
  EXPECT_EQ(c.cy, 1);
  EXPECT_EQ(c.r2, 2);
  const geometry::Circumellipse<double> d = geometry::circumellipse<double>({0, 0}, {1, 0}, {0, 2}, {4, 0, 1});
  EXPECT_EQ(d.cx, 0.5);
  EXPECT_EQ(d.cy, 1.0);
  EXPECT_EQ(d.r2, 2.0);
}

// The defining equations, exactly: d_M(c, a)² = d_M(c, b)² = d_M(c, c)² = r²; the interval
// evaluation encloses the exact centre and radius; the double one lies in the interval or within
// a few ulps of it relative to the magnitudes involved.
TEST(Circumellipse, ExactIsEquidistantAndIntervalEnclosesIt) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0, nearly_flat = 0;
  for (int k = 0; k < 2000; ++k) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    const Point2<double> a{u(rng) * scale, u(rng) * scale}, b{u(rng) * scale, u(rng) * scale};
    // One case in four nearly flat: c at a few ulps from the midpoint of ab (det ≈ 0, the centre far away).
    Point2<double> c{u(rng) * scale, u(rng) * scale};
    if (k % 4 == 0) {
      c = {a.x + (b.x - a.x) / 2, a.y + (b.y - a.y) / 2};
      for (int n = 1 + static_cast<int>(rng() % 4); n > 0; --n) c.y = std::nextafter(c.y, INFINITY);
      ++nearly_flat;
    }
    const Sym2<double> M = random_metric(rng);
    if (predicates::orientation(a, b, c) == Sign::zero) continue;
    ++checked;
    const auto e = geometry::circumellipse(exact(a), exact(b), exact(c), exact(M));
    const Sym2<Rational> m = exact(M);
    for (const Point2<double>& p : {a, b, c})
      EXPECT_EQ(predicates::quadratic_form(m.m11, m.m12, m.m22, e.cx - Rational(p.x), e.cy - Rational(p.y)), e.r2);
    const auto i = geometry::circumellipse(enclose(a), enclose(b), enclose(c), enclose(M));
    EXPECT_TRUE(contains(i.cx, e.cx) && contains(i.cy, e.cy) && contains(i.r2, e.r2)) << "case " << k;
    const auto d = geometry::circumellipse(a, b, c, M);
    if (std::isfinite(i.cx.lo) && std::isfinite(i.cx.hi)) {
      EXPECT_TRUE(d.cx >= i.cx.lo && d.cx <= i.cx.hi) << "case " << k;
    }
    if (std::isfinite(i.r2.lo) && std::isfinite(i.r2.hi)) {
      EXPECT_TRUE(d.r2 >= i.r2.lo && d.r2 <= i.r2.hi) << "case " << k;
    }
  }
  EXPECT_GT(checked, 1900);
  EXPECT_GT(nearly_flat, 400);
}

// The box of the M-ball, against the Cholesky parameterization of the ellipse, x = c + L⁻ᵀ(r u) with
// M = LLᵀ, |u| = 1: its x- and y-extents are r √(1 + (l21/l22)²)/l11 and r/l22 (maximize over u in
// closed form), which the double half-widths match to 10⁻¹²; sampled points lie inside the box;
// and the interval evaluation encloses the exact squared half-widths r² (M⁻¹)₁₁, r² (M⁻¹)₂₂.
TEST(EllipseBox, HalfWidthsAgainstTheInverseMetric) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 2 * 3.14159265358979);
  for (int k = 0; k < 1000; ++k) {
    const Sym2<double> M = random_metric(rng);
    const double r2 = std::ldexp(1.0, static_cast<int>(rng() % 20) - 10);
    const Sym2<Rational> m = exact(M);
    const Rational det = m.m11 * m.m22 - m.m12 * m.m12, hx2 = Rational(r2) * m.m22 / det, hy2 = Rational(r2) * m.m11 / det;
    const auto i = geometry::ellipse_half_widths(enclose(M), FilterInterval(r2));
    EXPECT_TRUE(contains(i.hx * i.hx, hx2) && contains(i.hy * i.hy, hy2)) << "case " << k;
    const auto d = geometry::ellipse_half_widths(M, r2);
    // M = LLᵀ (Cholesky); a point of the ellipse is c + L⁻ᵀ (r u).
    const double l11 = std::sqrt(M.m11), l21 = M.m12 / l11, l22 = std::sqrt(M.m22 - l21 * l21);
    EXPECT_NEAR(d.hx, std::sqrt(r2) * std::hypot(1.0, l21 / l22) / l11, 1e-12 * d.hx) << "case " << k;
    EXPECT_NEAR(d.hy, std::sqrt(r2) / l22, 1e-12 * d.hy) << "case " << k;
    for (int s = 0; s < 16; ++s) {
      const double t = u(rng), ux = std::sqrt(r2) * std::cos(t), uy = std::sqrt(r2) * std::sin(t);
      const double zy = uy / l22, zx = (ux - l21 * zy) / l11;
      EXPECT_LE(std::abs(zx), d.hx * (1 + 1e-9)) << "case " << k;
      EXPECT_LE(std::abs(zy), d.hy * (1 + 1e-9)) << "case " << k;
    }
  }
}

// τ(I, 4I) = 2 (LS Proposition 1: the stretch between the unit balls); τ(M, M) = 1; and on random
// pairs the double estimate brackets the exact τ² (decided by the exact predicate): within 10⁻⁹
// relative for unrelated metrics, and within 10⁻⁷ when one is a few ulps from the other (τ near 1:
// B² − 4AC cancels and its square root is only good to about √ε ≈ 10⁻⁸).
TEST(DistortionEstimate, AgreesWithTheExactComparison) {
  EXPECT_EQ(geometry::tau_squared_estimate<double>({1, 0, 1}, {4, 0, 4}), 4.0);
  std::mt19937 rng(7);
  for (int k = 0; k < 200; ++k) {
    const Sym2<double> M = random_metric(rng);
    EXPECT_NEAR(geometry::tau_squared_estimate(M, M), 1.0, 1e-9) << "case " << k;
  }
  for (int k = 0; k < 1000; ++k) {
    const Sym2<double> P = random_metric(rng);
    Sym2<double> Q = random_metric(rng);
    const bool nearly_equal = k % 3 == 0;
    if (nearly_equal) {
      Q = P;
      for (int n = 1 + static_cast<int>(rng() % 8); n > 0; --n) Q.m11 = std::nextafter(Q.m11, INFINITY);
    }
    const double t2 = geometry::tau_squared_estimate(P, Q), slack = nearly_equal ? 1e-7 : 1e-9;
    ASSERT_TRUE(std::isfinite(t2) && t2 >= 1 - slack) << "case " << k;
    EXPECT_EQ(predicates::compare_tau_squared(exact(P), exact(Q), Rational(t2 * (1 + slack))), Sign::negative) << "case " << k;
    if (!nearly_equal || t2 * (1 - slack) > 1) {  // below 1 there is nothing to bracket: τ ≥ 1 (LS Proposition 1)
      EXPECT_EQ(predicates::compare_tau_squared(exact(P), exact(Q), Rational(t2 * (1 - slack))), Sign::positive) << "case " << k;
    }
  }
}

// Point in polygon against a second method: the winding number by quadrant counting, exactly in
// rationals (a point on the boundary is inside the closed polygon); doubles and rationals give
// the same answer (one code, the exact orientation predicate).
int winding_number(const Point2<Rational>& p, const Polygon<Rational>& poly) {
  auto quadrant = [&](const Point2<Rational>& q) {
    const bool right = q.x > p.x, up = q.y > p.y;
    return right ? (up ? 0 : 3) : (up ? 1 : 2);
  };
  int turns = 0;  // in quarter turns
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Point2<Rational>& a = poly[k];
    const Point2<Rational>& b = poly[(k + 1) % poly.size()];
    int d = (quadrant(b) - quadrant(a) + 4) % 4;
    if (d == 2) d = predicates::orientation(a, b, p) == Sign::positive ? 2 : -2;  // crossing through the opposite quadrant
    if (d == 3) d = -1;
    turns += d;
  }
  return turns / 4;
}

TEST(Polygon, PointInPolygonAgreesWithTheWindingNumber) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coord(-32, 32);
  int inside = 0, boundary = 0;
  for (int k = 0; k < 400; ++k) {
    // A star-shaped polygon around the origin: corners at increasing angles, random radii.
    Polygon<double> poly;
    const int m = 3 + static_cast<int>(rng() % 8);
    for (int i = 0; i < m; ++i) {
      const double a = 2 * 3.14159265358979 * (i + 0.5 * std::uniform_real_distribution<double>(0, 1)(rng)) / m;
      const double r = 4 + static_cast<int>(rng() % 28);
      poly.push_back({std::round(r * std::cos(a)), std::round(r * std::sin(a))});
    }
    Polygon<Rational> exact_poly;
    for (const auto& q : poly) exact_poly.push_back(exact(q));
    if (geometry::simplicity_defect(exact_poly)) continue;
    for (int s = 0; s < 40; ++s) {
      const Point2<double> p = s < 4 ? poly[s % m] : Point2<double>{coord(rng) / 1.0, coord(rng) / 1.0};
      const bool on = [&] {
        for (int i = 0; i < m; ++i)
          if (geometry::on_segment(exact(p), exact_poly[i], exact_poly[(i + 1) % m])) return true;
        return false;
      }();
      const bool expected = on || winding_number(exact(p), exact_poly) != 0;
      EXPECT_EQ(geometry::in_closed_polygon(p, poly), expected) << "polygon " << k << ", point " << s;
      EXPECT_EQ(geometry::in_closed_polygon(exact(p), exact_poly), expected);
      inside += expected, boundary += on;
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(boundary, 100);
}

// Segment meeting against a second method: solving p1 + t(p2 − p1) = q1 + u(q2 − q1) by Cramer's
// rule in rationals (t, u ∈ (0, 1) with a non-zero determinant: a crossing unless an endpoint is on
// the other segment), and, for parallel segments, overlap of the parameter ranges on the line.
// On a grid of −4 … 4 most pairs have disjoint boxes and many boxes only touch.
geometry::Meeting meeting_by_parameters(const Point2<Rational>& p1, const Point2<Rational>& p2, const Point2<Rational>& q1,
                                        const Point2<Rational>& q2) {
  const Rational ax = p2.x - p1.x, ay = p2.y - p1.y, bx = q2.x - q1.x, by = q2.y - q1.y, cx = q1.x - p1.x, cy = q1.y - p1.y;
  const Rational det = ax * by - ay * bx;
  if (det != 0) {
    const Rational t = (cx * by - cy * bx) / det, u = (cx * ay - cy * ax) / det;
    if (t < 0 || t > 1 || u < 0 || u > 1) return geometry::Meeting::none;
    return (t == 0 || t == 1 || u == 0 || u == 1) ? geometry::Meeting::touching : geometry::Meeting::crossing;
  }
  if (cx * ay - cy * ax != 0) return geometry::Meeting::none;  // parallel, on different lines
  const Rational len = ax * ax + ay * ay;
  const Rational s0 = (cx * ax + cy * ay) / len, s1 = ((q2.x - p1.x) * ax + (q2.y - p1.y) * ay) / len;
  return std::max(s0, s1) < 0 || std::min(s0, s1) > 1 ? geometry::Meeting::none : geometry::Meeting::touching;
}

TEST(Polygon, SegmentMeetingAgreesWithTheParametricSolution) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> coord(-4, 4);  // a small grid: many collinear and touching cases
  int counts[3] = {0, 0, 0};
  for (int k = 0; k < 20000; ++k) {
    Point2<double> p[4];
    for (auto& q : p) q = {static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
    if ((p[0].x == p[1].x && p[0].y == p[1].y) || (p[2].x == p[3].x && p[2].y == p[3].y)) continue;
    const geometry::Meeting expected = meeting_by_parameters(exact(p[0]), exact(p[1]), exact(p[2]), exact(p[3]));
    EXPECT_EQ(geometry::segments_meet(p[0], p[1], p[2], p[3]), expected) << "case " << k;
    // segments_cross's box filter (disjoint boxes: no crossing) only spares orientations.
    EXPECT_EQ(geometry::segments_cross(p[0], p[1], p[2], p[3]), expected == geometry::Meeting::crossing) << "case " << k;
    ++counts[static_cast<int>(expected)];
  }
  for (int c : counts) EXPECT_GT(c, 1000);
}

}  // namespace

namespace {

// The split polygon against its definition, checked pointwise: random points on a random
// polygon's edges (at rational parameters), at its corners, on the extensions of its edges and
// off them. Every corner of the split polygon is a corner of Ω or a point on an edge; every point
// strictly inside an edge is a corner; consecutive corners lie on one edge of Ω, in order; the
// index of each corner's point is right.
TEST(SplitAtPoints, EveryPointOnAnEdgeBecomesACornerInOrder) {
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> coord(-20, 20), pick(0, 4), den(1, 9);
  for (int trial = 0; trial < 300; ++trial) {
    // A convex polygon: the hull of a regular-ish fan of rational points (counter-clockwise).
    const Polygon<Rational> omega = {{Rational(-10 + coord(rng) % 3), Rational(-10)}, {Rational(10), Rational(-10 + coord(rng) % 3)},
                                     {Rational(10 + coord(rng) % 3), Rational(10)}, {Rational(-10), Rational(10)}};
    const std::size_t m = omega.size();
    std::vector<Point2<Rational>> points;
    for (int k = 0; k < 12; ++k) {
      const auto& a = omega[static_cast<std::size_t>(k) % m];
      const auto& b = omega[(static_cast<std::size_t>(k) + 1) % m];
      const Rational t(coord(rng) % 10, den(rng) + 10);  // in (−1, 1): inside or on the extension
      switch (pick(rng)) {
        case 0: points.push_back(a); break;                                                        // a corner
        case 1: points.push_back({a.x + abs(t) * (b.x - a.x), a.y + abs(t) * (b.y - a.y)}); break;  // on the edge
        case 2: points.push_back({a.x - abs(t) * (b.x - a.x), a.y - abs(t) * (b.y - a.y)}); break;  // on its extension
        case 3: points.push_back({Rational(coord(rng), den(rng)), Rational(coord(rng), den(rng))}); break;
        default: if (!points.empty()) points.push_back(points.back());  // the same point twice
      }
    }
    const geometry::SplitPolygon s = geometry::split_at_points(omega, points);
    ASSERT_EQ(s.corners.size(), s.point.size());
    // Walk the split polygon: corner j lies on edge e(j) of Ω, e non-decreasing, each original
    // corner present, and between corners of one edge the distance from its start increases.
    std::size_t e = 0;
    for (std::size_t j = 0; j < s.corners.size(); ++j) {
      const auto& c = s.corners[j];
      const bool original = c.x == omega[e % m].x && c.y == omega[e % m].y;
      if (!original) {
        ASSERT_TRUE(geometry::on_segment(c, omega[e], omega[(e + 1) % m])) << "corner " << j;
        const auto& prev = s.corners[j - 1];
        const auto d = [&](const Point2<Rational>& p) { return abs(p.x - omega[e].x) + abs(p.y - omega[e].y); };
        EXPECT_LT(d(prev), d(c)) << "corner " << j;
      }
      if (s.point[j] >= 0) {
        EXPECT_EQ(points[static_cast<std::size_t>(s.point[j])].x, c.x);
        EXPECT_EQ(points[static_cast<std::size_t>(s.point[j])].y, c.y);
      } else {
        EXPECT_TRUE(original);
        for (const auto& p : points) EXPECT_FALSE(p.x == c.x && p.y == c.y) << "corner " << j << " is a point";
      }
      if (j + 1 < s.corners.size() && s.corners[j + 1].x == omega[(e + 1) % m].x && s.corners[j + 1].y == omega[(e + 1) % m].y)
        ++e;
    }
    EXPECT_EQ(e, m - 1);
    // Every point strictly inside an edge is a corner.
    for (std::size_t i = 0; i < points.size(); ++i) {
      bool on_edge = false;
      for (std::size_t k = 0; k < m; ++k) on_edge = on_edge || geometry::on_segment(points[i], omega[k], omega[(k + 1) % m]);
      bool corner = false;
      for (const auto& c : s.corners) corner = corner || (c.x == points[i].x && c.y == points[i].y);
      EXPECT_EQ(on_edge, corner) << "point " << i;
    }
  }
}

}  // namespace
