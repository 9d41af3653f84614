// LU §3.2's lemmas on quasi-cospherical configurations, in dimension 3 (issue 40), against the
// test's own exact computations (stars by gift wrapping, checked elsewhere against brute force;
// circumspheres by Cramer's rule in rationals); the decision of Definition 3.6 is
// predicates/quasi_cospherical.hpp's.
//  - LU.L38: a tetrahedron τ = (v, w, x, y) of S_v (Del_{M_v}) that is not in S_w (Del_{M_w}) has
//    a vertex p of S_w strictly inside C_{M_w}(τ) and not inside C_{M_v}(τ), and v, w, x, y, p
//    are γ₀-cospherical for M_v for every γ₀ > γ(M_v, M_w) (the proof's N = M_v, N′ = M_w).
//  - LU.L311: the explicit part of the proof of Lemma 3.11. For a tetrahedron τ with
//    M-circumcentre c and M-circumradius R, radius-edge ratio < ρ₀, every z for which
//    v, w, x, y, z are γ₀-cospherical with Definition 3.9's M-radius < βR lies in the M-shell
//      (1/γ₀ − C) R <= d_M(z, c) <= (γ₀ + C) R,  C = 7κγ₀(γ₀² − 1),  κ = √((2ρ₀)² + |β²γ₀² − 1|)
//    (the proof's last paragraph, its C taken from "d_N(c_N, c_N′) <= 7(γ₀² − 1)κR_N" with
//    R_N <= γ₀R). It holds for β <= 1 (the β < 1 of Lemmas 3.14–3.15, where it is used) and fails
//    for β > 1: then the bound on the configuration's radius is no bound (τ itself has radius
//    R < βR), and a sliver of radius-edge ratio 1/√2 has γ₀-cospherical points ten radii away
//    (LU_L311_3D.ShellFailsForSliversWhenBetaExceedsOne). The lemma's printed volume
//    f(γ₀) = 4/3 π((γ₀ + C)³ − (2 − 2γ₀ − C)³) does not tend to 0 (the inner term is negative
//    for every γ₀ > 1, so f > 4π/3); the shell's own volume 4/3 π((γ₀ + C)³ − (1/γ₀ − C)³) does.
//  - LU.L314: its proof's step "q, r, s, t are at M_p-distance less than 2βr_τ from p" fails for
//    any β (slivers again), and the number of configurations one insertion makes is not bounded
//    by any K(ρ₀, β) (LU_L314_3D.ConfigurationsReachFartherThanTwoBetaRTau). Theorem 4.5 needs
//    (1 − δ)³β > 2 where Lemmas 3.14–3.15 assume β < 1: the termination proof's sliver part does
//    not hold as written; the refiner's Pick_valid is a heuristic there (docs/refiners.md).
#include "predicates/distortion.hpp"
#include "predicates/insphere_perturbed.hpp"
#include "predicates/orientation3.hpp"
#include "predicates/quasi_cospherical.hpp"
#include "refiners/star/gift_wrap3.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <set>

using namespace anisocert;
using predicates::Point3;
using predicates::Sym3;

namespace {

using Q3 = std::array<Rational, 3>;

Q3 exact(const Point3<double>& p) { return {Rational(p.x), Rational(p.y), Rational(p.z)}; }

Rational form(const Sym3<Rational>& M, const Q3& u, const Q3& v) {
  return M.m11 * u[0] * v[0] + M.m22 * u[1] * v[1] + M.m33 * u[2] * v[2] + M.m12 * (u[0] * v[1] + u[1] * v[0]) +
         M.m13 * (u[0] * v[2] + u[2] * v[0]) + M.m23 * (u[1] * v[2] + u[2] * v[1]);
}

Q3 minus(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Rational det3(const std::array<Q3, 3>& A) {
  return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
         A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

// The M-circumsphere of four points (centre, squared radius): 2(t_i − t_0)ᵀM c = Q(t_i) − Q(t_0),
// i = 1, 2, 3, by Cramer's rule; none when they are coplanar.
std::optional<std::pair<Q3, Rational>> circumsphere(const std::array<Q3, 4>& t, const Sym3<Rational>& M) {
  std::array<Q3, 3> A;
  Q3 rhs;
  for (std::size_t i = 0; i < 3; ++i) {
    const Q3 e = minus(t[i + 1], t[0]);
    A[i] = {2 * form(M, e, {1, 0, 0}), 2 * form(M, e, {0, 1, 0}), 2 * form(M, e, {0, 0, 1})};
    rhs[i] = form(M, t[i + 1], t[i + 1]) - form(M, t[0], t[0]);
  }
  const Rational d = det3(A);
  if (d == 0) return std::nullopt;
  Q3 c;
  for (std::size_t k = 0; k < 3; ++k) {
    auto Ak = A;
    for (std::size_t i = 0; i < 3; ++i) Ak[i][k] = rhs[i];
    c[k] = det3(Ak) / d;
  }
  const Q3 r = minus(t[0], c);
  return std::pair{c, form(M, r, r)};
}

// A rational at least √x (x > 0 a rational that a double approximates well).
Rational sqrt_above(const Rational& x) {
  Rational s(std::nextafter(std::sqrt(x.convert_to<double>()), INFINITY));
  while (s * s < x) s *= Rational(1025, 1024);
  return s;
}

Sym3<double> lower_times_transpose(double l1, double l2, double l3, double l21, double l31, double l32) {
  return {l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32, l31 * l31 + l32 * l32 + l3 * l3};
}

// M = LLᵀ, L lower triangular with small integer entries (rotated, stretched up to about 9 : 1).
std::pair<Sym3<double>, std::array<double, 6>> random_metric() {
  const auto entry = [](int lo, int hi) { return static_cast<double>(*rc::gen::inRange(lo, hi + 1)); };
  const std::array<double, 6> L{entry(1, 3), entry(1, 3), entry(1, 3), entry(-2, 2), entry(-2, 2), entry(-2, 2)};
  return {lower_times_transpose(L[0], L[1], L[2], L[3], L[4], L[5]), L};
}

Sym3<Rational> exact(const Sym3<double>& M) { return {M.m11, M.m12, M.m13, M.m22, M.m23, M.m33}; }

}  // namespace

// LU Lemma 3.8 in 3D. Sites: v at the origin, the corners of the box [−5, 5]³ (v's star is
// closed) and random integer sites inside; every site its own random metric (independent
// metrics: inconsistencies are common). For each tetrahedron τ of S_v and each other vertex w of
// τ with τ not in S_w: a witness p among the vertices of S_w, inside C_{M_w}(τ) and not inside
// C_{M_v}(τ) (the perturbed tests the stars are built with), and v, w, x, y, p γ₀-cospherical for
// M_v (exact) with γ₀² twice the least power of 2 above γ(M_v, M_w)² (decided exactly).
RC_GTEST_PROP(LU_L38_3D, InconsistentTetrahedronHasAQuasiCosphericalWitness, ()) {
  std::vector<Point3<double>> p{{0, 0, 0}};
  std::set<std::array<double, 3>> seen{{0, 0, 0}};
  for (int k = 0; k < 8; ++k) p.push_back({k & 1 ? 5.0 : -5.0, k & 2 ? 5.0 : -5.0, k & 4 ? 5.0 : -5.0});
  const int interior = *rc::gen::inRange(6, 16);
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());  // (RapidCheck's inRange narrows with its size: too few distinct sites)
  std::uniform_int_distribution<int> coordinate(-4, 4);
  while (static_cast<int>(p.size()) < 9 + interior) {
    const Point3<double> q{double(coordinate(rng)), double(coordinate(rng)), double(coordinate(rng))};
    if (seen.insert({q.x, q.y, q.z}).second) p.push_back(q);
  }
  std::vector<Sym3<double>> M;
  for (std::size_t i = 0; i < p.size(); ++i) M.push_back(random_metric().first);
  const auto star = [&](int s) {
    std::vector<int> others;
    for (int i = 0; i < static_cast<int>(p.size()); ++i)
      if (i != s) others.push_back(i);
    return refiners::star::gift_wrap_star3(s, others, p, M[static_cast<std::size_t>(s)]);
  };
  const auto Sv = star(0);
  RC_ASSERT(Sv.open.empty());
  std::map<int, std::pair<std::set<std::array<int, 4>>, std::set<int>>> stars;  // w → (sorted tetrahedra, vertices)
  int inconsistent = 0;
  for (const auto& l : Sv.link) {
    const std::array<int, 4> tau{0, l[0], l[1], l[2]};  // positively oriented
    auto sorted = tau;
    std::sort(sorted.begin(), sorted.end());
    for (int w : l) {
      if (!stars.count(w)) {
        auto& [tetrahedra, vertices] = stars[w];
        for (const auto& t : star(w).link) {
          std::array<int, 4> s{w, t[0], t[1], t[2]};
          std::sort(s.begin(), s.end());
          tetrahedra.insert(s), vertices.insert(t.begin(), t.end());
        }
      }
      const auto& [tetrahedra, vertices] = stars[w];
      if (tetrahedra.count(sorted)) continue;
      ++inconsistent;
      const auto& Mv = M[0];
      const auto& Mw = M[static_cast<std::size_t>(w)];
      double g2 = 1;
      while (!predicates::tau_at_most(Mv, Mw, g2)) g2 *= 2;
      const double k = 4 * g2 * g2 - 1;  // γ₀⁴ − 1 for γ₀² = 2 g2 > γ(M_v, M_w)²
      bool witness = false;
      for (int q : vertices) {
        if (std::find(tau.begin(), tau.end(), q) != tau.end()) continue;
        const auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
        const std::array<Point3<double>, 5> five{at(tau[0]), at(tau[1]), at(tau[2]), at(tau[3]), at(q)};
        const std::array<int, 5> index{tau[0], tau[1], tau[2], tau[3], q};
        if (predicates::insphere_perturbed<double>(five, index, Mw) != Sign::positive) continue;
        if (predicates::insphere_perturbed<double>(five, index, Mv) == Sign::positive) continue;
        witness = true;
        RC_ASSERT(predicates::quasi_cospherical(five[0], five[1], five[2], five[3], five[4], Mv, k) == Sign::positive);
      }
      RC_ASSERT(witness);
    }
  }
  RC_TAG(inconsistent ? "inconsistent tetrahedra" : "consistent");
}

namespace {

// The shell of LU Lemma 3.11's proof, bounded outward: d_M(z, c)² against R² times the squares
// of γ₀ + C and 1/γ₀ − C computed with γ₀ and κ bounded above (the weakest shell the lemma
// implies, so an escape is the lemma's, not rounding's).
struct Shell {
  Rational outer, inner;  // inner <= 0: none
};

Shell lemma311_shell(const Rational& gamma0_above, const Rational& rho0_squared, const Rational& beta) {
  const Rational g = gamma0_above;
  const auto magnitude = [](const Rational& x) { return x < 0 ? Rational(-x) : x; };
  // |β²γ₀² − 1| for γ₀ in [1, g]: at most its larger value at the ends.
  const Rational excess = std::max(magnitude(beta * beta - 1), magnitude(beta * beta * g * g - 1));
  const Rational kappa = sqrt_above(4 * rho0_squared + excess);
  const Rational C = 7 * kappa * g * (g * g - 1);
  return {g + C, 1 / g - C};
}

// γ₀ = (1 + k)^(1/4) bounded above by a rational.
Rational gamma0_above(double k) {
  Rational g(std::nextafter(std::pow(1 + k, 0.25), INFINITY));
  while (g * g * g * g < 1 + Rational(k)) g *= Rational(1025, 1024);
  return g;
}

// The squared M-length of τ's shortest edge.
Rational shortest_edge2(const std::array<Q3, 4>& t, const Sym3<Rational>& M) {
  std::optional<Rational> least;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) {
      const Q3 e = minus(t[i], t[j]);
      if (const Rational l = form(M, e, e); !least || l < *least) least = l;
    }
  return *least;
}

// Definition 3.9's M-radius of five points (squared): the least M-circumradius of their
// non-coplanar fours.
Rational configuration_radius2(const std::array<Q3, 5>& x, const Sym3<Rational>& M) {
  std::optional<Rational> least;
  for (std::size_t skip = 0; skip < 5; ++skip) {
    std::array<Q3, 4> t;
    for (std::size_t i = 0, j = 0; i < 5; ++i)
      if (i != skip) t[j++] = x[i];
    if (const auto s = circumsphere(t, M); s && (!least || s->second < *least)) least = s->second;
  }
  return *least;  // τ itself is never coplanar
}

}  // namespace

// LU Lemma 3.11 in 3D, β <= 1. Random tetrahedra with integer vertices in random metrics
// M = LLᵀ, γ₀⁴ − 1 = 2⁻⁵, 2⁻⁷ or 2⁻¹⁰ (γ₀ ≈ 1.0077, 1.0019, 1.00024), β ∈ {1/2, 3/4, 9/10, 1},
// ρ₀ just above τ's ratio. Candidates z: most within a few (γ₀ − 1)R of a face's M-circumcircle
// (where the configurations with radius < βR are: a sphere through the face smaller than τ's),
// the rest anywhere within 2R of c. Every candidate the exact decision calls γ₀-cospherical with
// Definition 3.9's radius < βR (exact) lies in the shell.
RC_GTEST_PROP(LU_L311_3D, QuasiCosphericalPointsLieInTheProofsShell, ()) {
  const auto metric = random_metric();
  const Sym3<double>& Md = metric.first;
  const std::array<double, 6>& L = metric.second;
  const Sym3<Rational> M = exact(Md);
  std::array<Point3<double>, 4> td;
  for (auto& q : td) q = {double(*rc::gen::inRange(-6, 7)), double(*rc::gen::inRange(-6, 7)), double(*rc::gen::inRange(-6, 7))};
  RC_PRE(predicates::orientation3(td[0], td[1], td[2], td[3]) != Sign::zero);
  const std::array<Q3, 4> t{exact(td[0]), exact(td[1]), exact(td[2]), exact(td[3])};
  const auto [c, R2] = *circumsphere(t, M);
  const Rational rho0_squared = R2 / shortest_edge2(t, M) * Rational(1001, 1000);  // the ratio is < ρ₀
  const double k = *rc::gen::elementOf(std::vector<double>{0x1p-5, 0x1p-7, 0x1p-10});
  const Rational beta = *rc::gen::elementOf(std::vector<Rational>{Rational(1, 2), Rational(3, 4), Rational(9, 10), Rational(1)});
  const Rational g = gamma0_above(k);
  const Shell shell = lemma311_shell(g, rho0_squared, beta);

  // Candidates in y = Lᵀx (M becomes Euclidean), mapped back by x = L⁻ᵀy, in doubles: z is
  // whatever exact point results.
  const auto to_y = [&](const Point3<double>& x) {
    return std::array<double, 3>{L[0] * x.x + L[3] * x.y + L[4] * x.z, L[1] * x.y + L[5] * x.z, L[2] * x.z};
  };
  const auto to_x = [&](const std::array<double, 3>& y) {
    const double z = y[2] / L[2], yy = (y[1] - L[5] * z) / L[1];
    return Point3<double>{(y[0] - L[3] * yy - L[4] * z) / L[0], yy, z};
  };
  std::mt19937_64 rng(*rc::gen::arbitrary<std::uint32_t>());
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0, 1);
  const double R = std::sqrt(R2.convert_to<double>()), gamma_excess = std::pow(1 + k, 0.25) - 1;
  const std::array<double, 3> cy = to_y({c[0].convert_to<double>(), c[1].convert_to<double>(), c[2].convert_to<double>()});
  int qualifying = 0;
  for (int sample = 0; sample < 600; ++sample) {
    std::array<double, 3> zy;
    if (sample % 6 == 5) {
      for (std::size_t i = 0; i < 3; ++i) zy[i] = cy[i] + 2 * R * (2 * unit(rng) - 1);
    } else {
      const std::size_t skip = static_cast<std::size_t>(sample) % 4;
      std::array<std::array<double, 3>, 3> f;
      for (std::size_t i = 0, j = 0; i < 4; ++i)
        if (i != skip) f[j++] = to_y(td[i]);
      // The face's circumcircle in y: centre, radius, an orthonormal frame of its plane.
      const auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
      };
      const auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      };
      const auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
      const auto ab = sub(f[1], f[0]), ac = sub(f[2], f[0]), n = cross(ab, ac);
      const auto u1 = cross(n, ab), u2 = cross(ac, n);
      std::array<double, 3> centre, e1 = ab, e2 = cross(n, ab);
      for (std::size_t i = 0; i < 3; ++i) centre[i] = f[0][i] + (u1[i] * dot(ac, ac) + u2[i] * dot(ab, ab)) / (2 * dot(n, n));
      const double rf = std::sqrt(dot(sub(f[0], centre), sub(f[0], centre))), n1 = std::sqrt(dot(e1, e1)), n2 = std::sqrt(dot(e2, e2));
      const double theta = 2 * std::numbers::pi * unit(rng), spread = 4 * gamma_excess * R * unit(rng);
      for (std::size_t i = 0; i < 3; ++i)
        zy[i] = centre[i] + rf * (std::cos(theta) * e1[i] / n1 + std::sin(theta) * e2[i] / n2) + spread * normal(rng);
    }
    const Point3<double> zd = to_x(zy);
    if (predicates::quasi_cospherical(td[0], td[1], td[2], td[3], zd, Md, k) != Sign::positive) continue;
    const Q3 z = exact(zd);
    if (configuration_radius2({t[0], t[1], t[2], t[3], z}, M) >= beta * beta * R2) continue;
    ++qualifying;
    const Q3 r = minus(z, c);
    const Rational d2 = form(M, r, r);
    RC_ASSERT(d2 <= shell.outer * shell.outer * R2);
    if (shell.inner > 0) RC_ASSERT(d2 >= shell.inner * shell.inner * R2);
  }
  RC_TAG(qualifying == 0 ? "none qualifying" : qualifying < 20 ? "1-19 qualifying" : "20+ qualifying");
}

// LU Lemma 3.11 fails as stated for β > 1: τ = (1, 0, h), (0, 1, −h), (−1, 0, h), (0, −1, −h)
// under M = I (a sliver: its vertices within h of the unit circle, radius-edge ratio below
// ρ₀ = 3/4), γ₀⁴ − 1 = 2⁻⁸ (γ₀ ≈ 1.00098), z = (0, 0, D): the five are γ₀-cospherical (exact),
// Definition 3.9's radius is τ's own R (< βR for every β > 1, not < R), and d(z, c) = D while the
// shell ends at (γ₀ + C)R ≈ 1.032R. At h = 2⁻¹⁴, D = 10; at h = 2⁻²⁴, D = 1000: no f(γ₀) bounds
// W(τ)'s volume over the slivers of bounded radius-edge ratio.
TEST(LU_L311_3D, ShellFailsForSliversWhenBetaExceedsOne) {
  const double k = 0x1p-8;
  const Sym3<double> I{1, 0, 0, 1, 0, 1};
  const Shell shell = lemma311_shell(gamma0_above(k), Rational(9, 16), Rational(2));
  EXPECT_LT(shell.outer, Rational(104, 100));  // by hand: γ₀ + 7κγ₀(γ₀² − 1) ≈ 1.001 + 7 · 2.29 · 0.002 ≈ 1.032
  for (const auto& [h, D] : {std::pair{0x1p-14, 10.0}, std::pair{0x1p-24, 1000.0}}) {
    const std::array<Point3<double>, 4> td{{{1, 0, h}, {0, 1, -h}, {-1, 0, h}, {0, -1, -h}}};
    const Point3<double> zd{0, 0, D};
    EXPECT_EQ(predicates::quasi_cospherical(td[0], td[1], td[2], td[3], zd, I, k), Sign::positive) << "h = " << h;
    const std::array<Q3, 4> t{exact(td[0]), exact(td[1]), exact(td[2]), exact(td[3])};
    const auto sphere = *circumsphere(t, exact(I));
    const Rational hh = Rational(h) * Rational(h);
    // By hand: the four vertices are all at distance √(1 + h²) from the origin; the shortest edges
    // join neighbours, (1, 0, h) − (0, 1, −h) = (1, −1, 2h).
    EXPECT_EQ(sphere.first, (Q3{0, 0, 0}));
    EXPECT_EQ(sphere.second, 1 + hh);
    EXPECT_EQ(shortest_edge2(t, exact(I)), 2 + 4 * hh);
    EXPECT_LT(sphere.second / shortest_edge2(t, exact(I)), Rational(9, 16));  // radius-edge ratio < ρ₀ = 3/4
    EXPECT_EQ(configuration_radius2({t[0], t[1], t[2], t[3], exact(zd)}, exact(I)), sphere.second);  // qualifies for β > 1 only
    EXPECT_GT(Rational(D) * Rational(D), shell.outer * shell.outer * sphere.second);  // d(z, c)² = D² escapes the shell
  }
}

// LU Lemma 3.14's proof ("q, r, s, t are supposed to be at M_p-distance less than 2βr_τ from p")
// fails for the same reason, whatever β: p at the origin, inserted in the picking region of a
// face τ with r_τ = 2, β = 3/4 (so 2βr_τ = 3); eight slivers (1, 0, D + h), (0, 1, D − h),
// (−1, 0, D + h), (0, −1, D − h) at D = 10, 20, …, 80, h = 2⁻²⁴, under M = I. The sites are at
// least √2 apart (ε); each sliver with p is γ₀-cospherical (γ₀⁴ − 1 = 2⁻⁸, exact), its
// Definition 3.9 radius is the sliver's own (≈ 1 < βr_τ = 3/2) and its radius-edge ratio below
// ρ₀ = 3/4, yet its sites are 10 or more from p. More slivers farther out (h smaller) add more
// configurations: their number is bounded by no packing of the ball of radius 2βr_τ; it grows
// with how far Ω reaches in units of ε, which no constant K(ρ₀, β) bounds (argued, not tested).
TEST(LU_L314_3D, ConfigurationsReachFartherThanTwoBetaRTau) {
  const double k = 0x1p-8, h = 0x1p-24;
  const Sym3<double> I{1, 0, 0, 1, 0, 1};
  const Rational beta(3, 4), r_tau(2), epsilon2(2);
  const Point3<double> p{0, 0, 0};
  for (int i = 1; i <= 8; ++i) {
    const double D = 10.0 * i;
    const std::array<Point3<double>, 4> sliver{{{1, 0, D + h}, {0, 1, D - h}, {-1, 0, D + h}, {0, -1, D - h}}};
    ASSERT_EQ(predicates::quasi_cospherical(sliver[0], sliver[1], sliver[2], sliver[3], p, I, k), Sign::positive) << "D = " << D;
    const std::array<Q3, 4> t{exact(sliver[0]), exact(sliver[1]), exact(sliver[2]), exact(sliver[3])};
    const Rational r2 = configuration_radius2({t[0], t[1], t[2], t[3], exact(p)}, exact(I));
    EXPECT_LT(r2, beta * beta * r_tau * r_tau);
    EXPECT_GE(shortest_edge2(t, exact(I)), epsilon2);
    EXPECT_LT(r2 / shortest_edge2(t, exact(I)), Rational(9, 16));  // Definition 3.9's ratio (p is farther still)
    for (const auto& q : t) EXPECT_GT(form(exact(I), q, q), 4 * beta * beta * r_tau * r_tau);  // beyond 2βr_τ from p
  }
}
