// LU Definition 3.16 in dimension 3 (predicates/encroachment3.hpp, issue 40): the diametral
// M-ball of a facet against its centre solved here by Cramer's rule from its defining equations
// (equidistant from a, b, c in M; in the plane of abc, where the smallest ball through them is
// centred), with exact ties made on purpose (the antipode of a vertex); an edge's against closed
// forms; each kernel filtered on doubles against its exact sign.
#include "predicates/encroachment3.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using anisocert::Rational;
using anisocert::Sign;
using anisocert::predicates::Point3;
using anisocert::predicates::Sym3;

Rational form(const Sym3<Rational>& M, const std::array<Rational, 3>& x, const std::array<Rational, 3>& y) {
  const std::array<Rational, 3> My{M.m11 * y[0] + M.m12 * y[1] + M.m13 * y[2], M.m12 * y[0] + M.m22 * y[1] + M.m23 * y[2],
                                   M.m13 * y[0] + M.m23 * y[1] + M.m33 * y[2]};
  return x[0] * My[0] + x[1] * My[1] + x[2] * My[2];
}

Rational det3(const std::array<std::array<Rational, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The centre z of the diametral M-ball of abc, relative to a: uᵀMz = uᵀMu/2, vᵀMz = vᵀMv/2,
// (u × v)·z = 0, by Cramer's rule.
std::array<Rational, 3> diametral_centre(const std::array<Rational, 3>& u, const std::array<Rational, 3>& v, const Sym3<Rational>& M) {
  const auto row = [&](const std::array<Rational, 3>& x) {
    return std::array<Rational, 3>{form(M, x, {1, 0, 0}), form(M, x, {0, 1, 0}), form(M, x, {0, 0, 1})};
  };
  const std::array<Rational, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const std::array<std::array<Rational, 3>, 3> A{row(u), row(v), n};
  const std::array<Rational, 3> rhs{form(M, u, u) / 2, form(M, v, v) / 2, 0};
  const Rational d = det3(A);
  std::array<Rational, 3> z;
  for (std::size_t k = 0; k < 3; ++k) {
    auto Ak = A;
    for (std::size_t i = 0; i < 3; ++i) Ak[i][k] = rhs[i];
    z[k] = det3(Ak) / d;
  }
  return z;
}

Sym3<Rational> random_metric(std::mt19937& rng) {
  std::uniform_int_distribution<int> diagonal(1, 4), off(-3, 3);
  const Rational l1 = diagonal(rng), l2 = diagonal(rng), l3 = diagonal(rng), l21 = off(rng), l31 = off(rng), l32 = off(rng);
  return {l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32, l31 * l31 + l32 * l32 + l3 * l3};
}

}  // namespace

TEST(Encroachment3, FacetBallIsTheBallCentredInTheFacetsPlane) {
  std::mt19937 rng(316);
  std::uniform_int_distribution<int> coordinate(-16, 16), nudge(-1, 1);
  std::size_t inside = 0, outside = 0, on = 0;
  for (int round = 0; round < 600; ++round) {
    const auto point = [&] { return Point3<Rational>{Rational(coordinate(rng), 8), Rational(coordinate(rng), 8), Rational(coordinate(rng), 8)}; };
    const Point3<Rational> a = point(), b = point(), c = point();
    const std::array<Rational, 3> u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
    if (u[1] * v[2] == u[2] * v[1] && u[2] * v[0] == u[0] * v[2] && u[0] * v[1] == u[1] * v[0]) continue;  // collinear
    const Sym3<Rational> M = round % 3 == 0 ? Sym3<Rational>{1, 0, 0, 1, 0, 1} : random_metric(rng);
    const std::array<Rational, 3> z = diametral_centre(u, v, M);
    // A random point, and the antipode of a (exactly on the sphere) moved by 0 or ±2⁻⁴⁰ along x.
    Point3<Rational> p = round % 2 == 0 ? point() : Point3<Rational>{a.x + 2 * z[0], a.y + 2 * z[1], a.z + 2 * z[2]};
    if (round % 2 == 1) p.x += Rational(nudge(rng)) / (Rational(1ULL << 40));
    const std::array<Rational, 3> w{p.x - a.x, p.y - a.y, p.z - a.z}, wz{w[0] - z[0], w[1] - z[1], w[2] - z[2]};
    const Rational excess = form(M, wz, wz) - form(M, z, z);  // Q(p − centre) − Q(a − centre)
    const std::array<Rational, 18> x{p.x, p.y, p.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, M.m11, M.m12, M.m13, M.m22, M.m23, M.m33};
    const Sign s = anisocert::predicates::high_degree_sign<anisocert::predicates::DiametralSphereKernel>(x);
    ASSERT_EQ(s, excess > 0 ? Sign::positive : excess < 0 ? Sign::negative : Sign::zero) << "round " << round;
    EXPECT_EQ(anisocert::predicates::encroaches_facet(p, a, b, c, M), excess < 0);
    inside += excess < 0, outside += excess > 0, on += excess == 0;
    // The vertices are on the sphere.
    for (const auto& q : {a, b, c}) EXPECT_FALSE(anisocert::predicates::encroaches_facet(q, a, b, c, M));
  }
  EXPECT_GT(inside, 50u);
  EXPECT_GT(outside, 50u);
  EXPECT_GT(on, 50u);
}

TEST(Encroachment3, EdgeBallClosedForms) {
  // M = diag(4, 1, 1), a = (−1, 0, 0), b = (1, 0, 0): the diametral M-ball is 4x² + y² + z² < 4.
  const Sym3<Rational> M{4, 0, 0, 1, 0, 1};
  const Point3<Rational> a{-1, 0, 0}, b{1, 0, 0};
  using anisocert::predicates::encroaches_edge;
  EXPECT_FALSE(encroaches_edge(Point3<Rational>{0, 2, 0}, a, b, M));  // −4 + 4 = 0: on
  EXPECT_FALSE(encroaches_edge(Point3<Rational>{0, 0, 2}, a, b, M));
  EXPECT_TRUE(encroaches_edge(Point3<Rational>{0, 1, 1}, a, b, M));   // −4 + 2 < 0
  EXPECT_FALSE(encroaches_edge(Point3<Rational>{0, 2, 1}, a, b, M));  // −4 + 5 > 0
  EXPECT_FALSE(encroaches_edge(Point3<Rational>{1, 1, 0}, a, b, M));  // (−2, −1, 0)M(0, −1, 0) = 1 > 0
  EXPECT_TRUE(encroaches_edge(Point3<Rational>{Rational(1, 2), 1, 0}, a, b, M));  // 4·(−3/2)(1/2) + 1 = −2 < 0
}

// Doubles with full mantissas, and exact ties in doubles (a facet's vertex as p; the edge's
// endpoints): the filtered sign equals the exact sign of the rationals they denote.
TEST(Encroachment3, FilteredSignsAreTheExactOnes) {
  std::mt19937 rng(3160);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::uniform_int_distribution<int> which(0, 3);
  for (int round = 0; round < 3000; ++round) {
    std::array<double, 18> x;
    for (std::size_t i = 0; i < 12; ++i) x[i] = 1000 + coordinate(rng);  // far from the origin: the translated stage
    const int k = which(rng);
    if (k > 0) x[0] = x[3 * static_cast<std::size_t>(k)], x[1] = x[3 * static_cast<std::size_t>(k) + 1], x[2] = x[3 * static_cast<std::size_t>(k) + 2];
    const double l1 = 1 + coordinate(rng) * coordinate(rng), l2 = 1.5, l3 = 0.75, l21 = coordinate(rng), l31 = coordinate(rng), l32 = coordinate(rng);
    const std::array<double, 6> m{l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32, l31 * l31 + l32 * l32 + l3 * l3};
    for (std::size_t i = 0; i < 6; ++i) x[12 + i] = m[i];
    std::array<Rational, 18> q;
    for (std::size_t i = 0; i < 18; ++i) q[i] = Rational(x[i]);
    using anisocert::predicates::DiametralSphereKernel;
    using anisocert::predicates::MetricDot3Kernel;
    const Rational exact = DiametralSphereKernel::eval(q);
    ASSERT_EQ(anisocert::predicates::high_degree_sign<DiametralSphereKernel>(x), exact > 0 ? Sign::positive : exact < 0 ? Sign::negative : Sign::zero) << round;
    std::array<double, 15> y;
    std::array<Rational, 15> r;
    for (std::size_t i = 0; i < 9; ++i) y[i] = x[i], r[i] = q[i];
    for (std::size_t i = 0; i < 6; ++i) y[9 + i] = x[12 + i], r[9 + i] = q[12 + i];
    const Rational dot = MetricDot3Kernel::eval(r);
    ASSERT_EQ(anisocert::predicates::filtered_sign<MetricDot3Kernel>(y), dot > 0 ? Sign::positive : dot < 0 ? Sign::negative : Sign::zero) << round;
  }
}
