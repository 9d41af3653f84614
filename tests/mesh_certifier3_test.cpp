// The exact certifier of tetrahedral meshes (oracle/certify/mesh_certifier3.hpp) on meshes whose
// answers are known by hand: Kuhn-subdivided grids of unit cubes (each cube's six tetrahedra share
// its circumsphere, on which its eight corners lie and no other grid point: distances² from the
// centre are Σ (k − 1/2)², 3/4 only for k ∈ {0, 1}), two tetrahedra across a face that break the
// Delaunay condition, and metric lengths at the exact boundary √2.

#include "geometry/kuhn_grid.hpp"
#include "oracle/certify/mesh_certifier3.hpp"
#include "witness_lists.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using anisocert::Rational;
using anisocert::Sign;
using namespace anisocert::oracle;
using Mesh3 = anisocert::geometry::Mesh3<Rational>;
using anisocert::predicates::Sym3;

namespace {

// The n × n × n Kuhn grid (geometry/kuhn_grid.hpp) with metric M everywhere.
Mesh3 kuhn_grid(int n, const Sym3<Rational>& M) {
  Mesh3 m = anisocert::geometry::kuhn_grid(n);
  m.metrics.assign(m.vertices.size(), M);
  return m;
}

Certify3Options all_checks() {
  Certify3Options o;
  o.metric = true;
  return o;
}

}  // namespace

// 2 × 2 × 2 cubes: 48 tetrahedra, valid; locally uniform with every test a tie or outside: each
// tetrahedron's sphere holds the other four corners of its cube, and nothing else. One witness
// per tetrahedron, as in 2D: 48 ties (one each, the first found), no violation.
TEST(MeshCertifier3, TheKuhnGridIsValidAndDelaunayWithTies) {
  const Mesh3 m = kuhn_grid(2, {1, 0, 0, 1, 0, 1});
  const Certify3Report r = certify_mesh3(m, all_checks());
  ASSERT_TRUE(r.valid);
  EXPECT_TRUE(r.valid_holds());
  EXPECT_EQ(r.tetrahedra, 48u);
  EXPECT_TRUE(r.uniform_checked);
  EXPECT_EQ(r.uniform_violations.count(), 0u);
  EXPECT_EQ(r.uniform_ties.count(), 48u);
  EXPECT_TRUE(r.holds(all_checks()));
  // The same grid stretched by M = diag(1, 4, 9) in every metric, its coordinates divided by
  // (1, 2, 3): the picture is the Euclidean one, ties included.
  Mesh3 s = m;
  for (auto& p : s.vertices) p.y /= 2, p.z /= 3;
  s.metrics.assign(s.vertices.size(), Sym3<Rational>{1, 0, 0, 4, 0, 9});
  const Certify3Report t = certify_mesh3(s, all_checks());
  EXPECT_EQ(t.uniform_violations.count(), 0u);
  EXPECT_EQ(t.uniform_ties.count(), 48u);
}

// Two tetrahedra across the face (0,0,0), (1,0,0), (0,1,0): apexes (0,0,1) and (3/10, 3/10, −1/10).
// The first one's sphere (centre (1/2, 1/2, 1/2), radius² 3/4) holds the second apex (distance²
// 0.44), and then the second's holds the first apex (the in-sphere test of five points does not
// depend on which four make the tetrahedron, up to orientation): each tetrahedron has one vertex
// inside, named once (its search stops there): 2 violations. The mesh is valid.
TEST(MeshCertifier3, AFaceThatShouldFlipIsNamedFromBothSides) {
  Mesh3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {Rational(3, 10), Rational(3, 10), Rational(-1, 10)}};
  m.tetrahedra = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  m.metrics.assign(5, Sym3<Rational>{1, 0, 0, 1, 0, 1});
  const Certify3Report r = certify_mesh3(m, all_checks());
  EXPECT_TRUE(r.valid_holds());
  EXPECT_EQ(r.uniform_violations.count(), 2u);
  EXPECT_EQ(r.uniform_ties.count(), 0u);
  ASSERT_FALSE(r.uniform_violations.described().empty());
  EXPECT_NE(r.uniform_violations.described()[0].text.find("strictly inside the circumsphere of tetrahedron 0"), std::string::npos);
  EXPECT_FALSE(r.holds(all_checks()));
  // A metric that squashes z by 1/100 (M = diag(1, 1, 10⁴)) keeps every sphere thin in z: the
  // apex at z = −1/10 is then far outside the first tetrahedron's ellipsoid in its vertices' metrics.
  m.metrics.assign(5, Sym3<Rational>{1, 0, 0, 1, 0, 10000});
  const Certify3Report s = certify_mesh3(m, all_checks());
  EXPECT_EQ(s.uniform_violations.count(), 0u);
  // Every vertex's own metric is asked: with M = I at vertex 2 only (third in the first
  // tetrahedron, second in the other), each tetrahedron is caught in vertex 2's metric alone.
  m.metrics[2] = Sym3<Rational>{1, 0, 0, 1, 0, 1};
  const Certify3Report u = certify_mesh3(m, all_checks());
  ASSERT_EQ(u.uniform_violations.count(), 2u);
  for (const auto& w : u.uniform_violations.described()) EXPECT_EQ(w.vertex, 2) << w.text;
}

// One Kuhn cube, M = I: its 19 edges are the 12 cube edges (length 1), 6 face diagonals (√2,
// exactly the upper end of [1/√2, √2], which is closed) and the diagonal (√3): 18 unit edges.
// With M = I/2 (lengths ÷ √2) the diagonals √3/√2 ≈ 1.22 are in and the cube edges 1/√2 are too
// (exactly the lower end): 19.
TEST(MeshCertifier3, UnitEdgesAreDecidedExactlyAtTheEnds) {
  Mesh3 m = kuhn_grid(1, {1, 0, 0, 1, 0, 1});
  const Certify3Report r = certify_mesh3(m, all_checks());
  ASSERT_TRUE(r.lengths);
  EXPECT_EQ(r.lengths->edges, 19u);
  EXPECT_EQ(r.lengths->unit_edges, 18u);
  m.metrics.assign(m.vertices.size(), Sym3<Rational>{Rational(1, 2), 0, 0, Rational(1, 2), 0, Rational(1, 2)});
  const Certify3Report h = certify_mesh3(m, all_checks());
  EXPECT_EQ(h.lengths->unit_edges, 19u);
  // A range as a verdict: [1, 1] in M = I holds for the 12 cube edges only.
  Certify3Options o = all_checks();
  o.length_range = {Rational(1), Rational(1)};
  m.metrics.assign(m.vertices.size(), Sym3<Rational>{1, 0, 0, 1, 0, 1});
  const Certify3Report g = certify_mesh3(m, o);
  EXPECT_EQ(g.lengths->range_violations.count(), 7u);
  EXPECT_FALSE(g.holds(o));
}

namespace {

using Point = anisocert::predicates::Point3<Rational>;

// Per tetrahedron, from scratch in rationals: whether some vertex lies strictly inside its
// M_v-circumsphere for one of its vertices v, and whether some lies on one. The centre a + x
// solves 2(q − a)ᵀ M x = (q − a)ᵀ M (q − a), q = b, c, d, by Gauss–Jordan elimination; r² = xᵀMx.
struct Truth {
  bool inside = false, on = false;
};

Rational form(const Sym3<Rational>& M, const std::array<Rational, 3>& d) {
  return M.m11 * d[0] * d[0] + M.m22 * d[1] * d[1] + M.m33 * d[2] * d[2] +
         2 * (M.m12 * d[0] * d[1] + M.m13 * d[0] * d[2] + M.m23 * d[1] * d[2]);
}

std::array<Rational, 3> minus(const Point& p, const Point& q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }

std::vector<Truth> brute_force(const Mesh3& m) {
  std::vector<Truth> truth(m.tetrahedra.size());
  for (std::size_t ti = 0; ti < m.tetrahedra.size(); ++ti) {
    const auto& t = m.tetrahedra[ti];
    const Point& a = m.vertices[static_cast<std::size_t>(t[0])];
    for (const int v : t) {
      const Sym3<Rational>& M = m.metrics[static_cast<std::size_t>(v)];
      std::array<std::array<Rational, 4>, 3> A;
      for (std::size_t k = 0; k < 3; ++k) {
        const auto d = minus(m.vertices[static_cast<std::size_t>(t[k + 1])], a);
        const std::array<Rational, 3> Md{M.m11 * d[0] + M.m12 * d[1] + M.m13 * d[2], M.m12 * d[0] + M.m22 * d[1] + M.m23 * d[2],
                                         M.m13 * d[0] + M.m23 * d[1] + M.m33 * d[2]};
        A[k] = {2 * Md[0], 2 * Md[1], 2 * Md[2], form(M, d)};
      }
      bool flat = false;
      for (std::size_t c = 0; c < 3 && !flat; ++c) {
        std::size_t pivot = c;
        while (pivot < 3 && A[pivot][c] == 0) ++pivot;
        if (pivot == 3) {
          flat = true;
          break;
        }
        std::swap(A[c], A[pivot]);
        for (std::size_t r = 0; r < 3; ++r)
          if (r != c && A[r][c] != 0) {
            const Rational f = A[r][c] / A[c][c];
            for (std::size_t j = c; j < 4; ++j) A[r][j] -= f * A[c][j];
          }
      }
      if (flat) break;  // a flat tetrahedron is not measured
      const std::array<Rational, 3> x{A[0][3] / A[0][0], A[1][3] / A[1][1], A[2][3] / A[2][2]};
      const Rational r2 = form(M, x);
      for (std::size_t e = 0; e < m.vertices.size(); ++e) {
        if (std::find(t.begin(), t.end(), static_cast<int>(e)) != t.end()) continue;
        const auto d = minus(m.vertices[e], a);
        const Rational q = form(M, {d[0] - x[0], d[1] - x[1], d[2] - x[2]});
        truth[ti].inside = truth[ti].inside || q < r2, truth[ti].on = truth[ti].on || q == r2;
      }
    }
  }
  return truth;
}

}  // namespace

// Filters only speed up, never change, an answer: the locally uniform verdicts (the interval
// box, the interval sphere test that spares candidates certainly outside, the interval in-sphere
// determinant, the rational fall-back) against brute_force above, per tetrahedron, on 2 × 2 × 2
// Kuhn grids whose interior vertex and face centres are moved by 0, a sixteenth, 2⁻⁶⁰ (no double
// nearby: the filters must defer) or 10⁻¹⁸, under M = I (every cube cospherical: ties), random
// diagonal metrics, and random rational metrics LLᵀ per vertex. Violations must be exactly the
// tetrahedra with a vertex inside; one tie is recorded per tetrahedron at most, before any
// violation, so the tied ones lie between those with only ties and those with any.
TEST(MeshCertifier3, FiltersNeverChangeTheUniformVerdict) {
  std::mt19937 rng(2027);
  std::uniform_int_distribution<int> small(-3, 3), pick(0, 3), kind(0, 2);
  const std::array<Rational, 4> moves{Rational(0), Rational(1, 16), Rational(1, 1ULL << 60), Rational(1, 1000000000000000000ULL)};
  std::size_t violated = 0, tied = 0;
  for (int round = 0; round < 40; ++round) {
    Mesh3 m = anisocert::geometry::kuhn_grid(2);
    for (auto& p : m.vertices) {
      const bool interior = p.x == 1 || p.y == 1 || p.z == 1;
      if (!interior || pick(rng) == 0) continue;
      p.x += small(rng) * moves[static_cast<std::size_t>(pick(rng))], p.y += small(rng) * moves[static_cast<std::size_t>(pick(rng))];
      p.z += small(rng) * moves[static_cast<std::size_t>(pick(rng))];
    }
    const int k = kind(rng);
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      if (k == 0) {
        m.metrics.push_back({1, 0, 0, 1, 0, 1});
      } else if (k == 1) {
        const Rational d1 = 1 + pick(rng), d2(1 + pick(rng), 2), d3 = 2 + pick(rng);
        m.metrics.push_back({d1, 0, 0, d2, 0, d3});
      } else {  // L = [[l1, 0, 0], [l21, l2, 0], [l31, l32, l3]], M = LLᵀ
        const Rational l1 = 1 + pick(rng), l2 = 1 + pick(rng), l3(1 + pick(rng), 2), l21(small(rng), 4), l31(small(rng), 4),
                       l32(small(rng), 4);
        m.metrics.push_back({l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32, l31 * l31 + l32 * l32 + l3 * l3});
      }
    }
    Certify3Options o;
    o.described_witnesses = 1000;
    const Certify3Report r = certify_mesh3(m, o);
    const std::vector<Truth> truth = brute_force(m);
    std::vector<char> got_violation(m.tetrahedra.size(), 0), got_tie(m.tetrahedra.size(), 0);
    for (const auto& w : r.uniform_violations.described()) got_violation[static_cast<std::size_t>(w.triangle)] = 1;
    for (const auto& w : r.uniform_ties.described()) got_tie[static_cast<std::size_t>(w.triangle)] = 1;
    for (std::size_t t = 0; t < truth.size(); ++t) {
      EXPECT_EQ(static_cast<bool>(got_violation[t]), truth[t].inside) << "round " << round << ", tetrahedron " << t;
      if (truth[t].on && !truth[t].inside) {
        EXPECT_TRUE(got_tie[t]) << "round " << round << ", tetrahedron " << t;
      }
      if (got_tie[t]) {
        EXPECT_TRUE(truth[t].on) << "round " << round << ", tetrahedron " << t;
      }
      violated += truth[t].inside, tied += truth[t].on;
    }
  }
  // The cases are not all one kind: both violations and ties occur.
  EXPECT_GT(violated, 100u);
  EXPECT_GT(tied, 30u);
}

// Nearly flat tetrahedra in stretched metrics, where intervals cannot bound the circumcentre (the
// determinant's enclosure holds 0: the certifier encloses the exact centre instead of testing
// every vertex): a, b, c = the unit points on the axes and d = g ± 2⁻ᵏ (1, 1, 1), g = (1/3, 1/3, 1/3)
// their centroid, k = 40 … 90 (1/3 is no double: intervals, whose determinant cancels in the
// tilted plane), whose huge sphere's centre lies far beyond the plane, under diag(1, 1, s) for
// s = 1 … 10⁴; other vertices at g + (1, 1, 1)/2ʲ on d's side (outside: the sphere rises about
// 2⁻ᵏ there) or on both (inside beyond the plane), and one in the plane off the circle; and the
// same in the plane z = 1/3 (a centre far along z, whose side a wrong enclosure would mistake). The verdict per tetrahedron is
// brute_force's (a centre enclosed on the wrong side, or too small a box, loses the violations).
TEST(MeshCertifier3, NearlyFlatTetrahedraInStretchedMetricsAreSearchedExactly) {
  std::size_t violated = 0, clean = 0;
  for (int k = 40; k <= 90; k += 10)
    for (const int sign : {1, -1})
      for (const Rational& s : {Rational(1), Rational(100), Rational(10000)})
        for (const bool both_sides : {false, true})
          for (const bool tilted : {true, false}) {
        Mesh3 m;
        const Rational third(1, 3), tiny = Rational(sign) / Rational(anisocert::Integer(1) << k);
        const auto on_axis = [&](const Rational& h) { return tilted ? Point{third + h, third + h, third + h} : Point{third, third, third + h}; };
        if (tilted) {
          m.vertices = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, on_axis(tiny)};
        } else {
          m.vertices = {{0, 0, third}, {1, 0, third}, {0, 1, third}, on_axis(tiny)};
        }
        for (int j = 1; j <= 6; ++j) m.vertices.push_back(on_axis(Rational(both_sides && j % 2 ? -sign : sign) / Rational(1 << j)));
        m.vertices.push_back(tilted ? Point{1, 1, -1} : Point{1, 1, third});
        m.tetrahedra = {{0, 1, 2, 3}};
        m.metrics.assign(m.vertices.size(), Sym3<Rational>{1, 0, 0, 1, 0, s});
        Certify3Options o;
        o.valid = false;
        o.described_witnesses = 10;
        const Certify3Report r = certify_mesh3(m, o);
        const bool inside = brute_force(m)[0].inside;
        EXPECT_EQ(!r.uniform_violations.empty(), inside) << "k " << k << ", sign " << sign << ", s " << s;
        (inside ? violated : clean) += 1;
          }
  EXPECT_GT(violated, 0u);
  EXPECT_GT(clean, 0u);
}

// The mean ratio of tetrahedra, 12 (3 V_M)^(2/3) / Σ ℓ_M², by hand: a Kuhn tetrahedron has
// |D| = 1 (six volumes) and edges 1, 1, 1, √2, √2, √3 (Σ ℓ² = 10), so q³ = 432 / 1000 and
// q = 0.7560 for M = I: a bound of 3/4 (27/64 < 432/1000) holds and 19/25 (6859/15625 > 432/1000)
// fails for all 48 tetrahedra of the 2 × 2 × 2 grid. The regular tetrahedron (1, 1, 1),
// (1, −1, −1), (−1, 1, −1), (−1, −1, 1) has quality exactly 1: the bound 1 holds (the exact
// boundary), and fails once M = diag(1, 1, 4) stretches it.
TEST(MeshCertifier3, MeanRatioQualityIsDecidedExactly) {
  Certify3Options o = all_checks();
  const Mesh3 grid = kuhn_grid(2, {1, 0, 0, 1, 0, 1});
  o.min_quality = Rational(3, 4);
  const Certify3Report a = certify_mesh3(grid, o);
  ASSERT_TRUE(a.quality);
  EXPECT_EQ(a.quality->measured, 48u);
  EXPECT_TRUE(a.quality->violations.empty());
  EXPECT_LE(a.quality->worst.lo, 0.7559527);  // 0.432^(1/3) = 0.75595263...
  EXPECT_GE(a.quality->worst.hi, 0.7559526);
  o.min_quality = Rational(19, 25);
  EXPECT_EQ(certify_mesh3(grid, o).quality->violations.count(), 48u);
  Mesh3 regular;
  regular.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  regular.tetrahedra = {{0, 1, 2, 3}};
  regular.metrics.assign(4, Sym3<Rational>{1, 0, 0, 1, 0, 1});
  o.min_quality = Rational(1);
  const Certify3Report r = certify_mesh3(regular, o);
  EXPECT_TRUE(r.quality->violations.empty());
  EXPECT_TRUE(r.holds(o));
  regular.metrics.assign(4, Sym3<Rational>{1, 0, 0, 1, 0, 4});
  EXPECT_EQ(certify_mesh3(regular, o).quality->violations.count(), 1u);
}

// UGAWG's measures (oracle/certify/ugawg_measures.hpp), against closed forms and Omega_h's own unit
// test (a regular tetrahedron squashed by 1/2 in z has quality 1 in diag(1, 1, 4)).
TEST(UgawgMeasures, ClosedFormsAndTheLargestDeterminantMetric) {
  EXPECT_DOUBLE_EQ(log_interpolated_length(1, 2), 1 / std::log(2.0));  // (1 − 2) / ln(1/2)
  EXPECT_DOUBLE_EQ(log_interpolated_length(2, 1), 1 / std::log(2.0));
  EXPECT_EQ(log_interpolated_length(3, 3), 3);
  using P = anisocert::predicates::Point3<double>;
  const std::array<P, 4> regular{P{1, 1, 1}, P{1, -1, -1}, P{-1, 1, -1}, P{-1, -1, 1}};  // edges 2√2, D = −16
  const Sym3<double> I{1, 0, 0, 1, 0, 1}, four{4, 0, 0, 4, 0, 4}, z4{1, 0, 0, 1, 0, 4};  // m11 m12 m13 m22 m23 m33
  EXPECT_NEAR(omega_h_quality(regular, I), -1, 1e-14);
  EXPECT_NEAR(omega_h_quality({regular[1], regular[0], regular[2], regular[3]}, four), 1, 1e-14);
  std::array<P, 4> squashed = {regular[1], regular[0], regular[2], regular[3]};
  for (auto& p : squashed) p.z /= 2;
  EXPECT_NEAR(omega_h_quality(squashed, z4), 1, 1e-14);
  EXPECT_LT(omega_h_quality(squashed, I), 0.9);
  // The squashed tetrahedron as a mesh, one vertex with diag(1, 1, 4) (the largest determinant):
  // Omega_h measures it in that metric, so its quality is 1; edge 0–1 has length 2√2 in I at one
  // end and in diag(1, 1, 4) at the other, as it is horizontal.
  Mesh3 m;
  for (const auto& p : squashed) m.vertices.push_back({Rational(p.x), Rational(p.y), Rational(p.z)});
  m.tetrahedra = {{0, 1, 2, 3}};
  m.metrics.assign(4, Sym3<Rational>{1, 0, 0, 1, 0, 1});
  m.metrics[2] = Sym3<Rational>{1, 0, 0, 1, 0, 4};
  const EnclosedMesh3 e(m);
  const UgawgMeasures u = ugawg_measures(e, {{0, 1}, {0, 2}}, 1);
  EXPECT_EQ(u.edges, 2u);
  EXPECT_NEAR(u.least_quality, 1, 1e-14);
  EXPECT_EQ(u.quality_bins[9], 1u);
  // Edge 0–2 from (1, −1, −1/2) to (−1, 1, −1/2): 2√2 in both metrics (no z part); edge 0–1 from
  // (1, −1, −1/2) to (1, 1, 1/2): √5 in I at both ends.
  EXPECT_NEAR(u.shortest, std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(u.longest, 2 * std::sqrt(2.0), 1e-14);
  EXPECT_EQ(u.unit_edges, 0u);
  EXPECT_NEAR(ugawg_measures(e, {}, -1).least_quality, -1, 1e-14);
}

// Dihedral angles on the Kuhn grid: every Kuhn tetrahedron (a path 0 → e_i → e_i + e_j → 1 through
// the cube) has three right dihedral angles, two of 60° and one of 45° (Coxeter's orthoscheme), so
// in the identity the smallest is 45° and the largest 90°; 45° is a bound met exactly (sin² = 1/2),
// 45° + 10⁻²⁰ is not; in M = 4·I (a scaling) nothing changes.
TEST(MeshCertifier3, DihedralAnglesOfTheKuhnGridAre45_60_90) {
  for (const Rational& s : {Rational(1), Rational(4)}) {
    const Mesh3 m = kuhn_grid(2, {s, 0, 0, s, 0, s});
    const EnclosedMesh3 e(m);
    const AngleReport r = check_angles(e, Rational(45));
    EXPECT_EQ(r.measured, m.tetrahedra.size());
    EXPECT_NEAR(r.smallest, 45, 1e-9);
    EXPECT_NEAR(r.largest, 90, 1e-9);
    EXPECT_TRUE(r.violations.empty());
    EXPECT_TRUE(r.undecided_triangles.empty());
    const AngleReport above = check_angles(e, Rational(45) + 1 / Rational("100000000000000000000"));
    EXPECT_EQ(above.violations.count(), m.tetrahedra.size());  // one witness per tetrahedron
    EXPECT_TRUE(check_angles(e, Rational(44)).violations.empty());
  }
}

// LU's bounds in 3D on one tetrahedron whose ratios are rational by hand: 0, 2e₁, 2e₂, e₃ has its
// circumcentre at (1, 1, 1/2) (equidistant: 1 + 1 + 1/4 = 9/4 from each corner) and its shortest
// edge 1 (0 to e₃), so ρ = 3/2 exactly in I (and in 4·I: ρ is scale-free); the distortion between I
// and diag(1, 4, 9) is 3 (the generalized eigenvalues 1, 4, 9).
TEST(MeshCertifier3, RadiusEdgeAndDistortionBoundsAreDecidedExactly) {
  Mesh3 m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}};
  m.tetrahedra = {{0, 1, 2, 3}};
  m.metrics.assign(4, Sym3<Rational>{4, 0, 0, 4, 0, 4});
  Certify3Options o;
  o.valid = false, o.uniform = false;
  o.rho0 = Rational(3, 2);
  Certify3Report r = certify_mesh3(m, o);
  EXPECT_TRUE(r.rho_violations.empty());
  EXPECT_NEAR(r.worst_rho, 1.5, 1e-12);
  o.rho0 = Rational(3, 2) - Rational(1, 1000000000000);
  EXPECT_EQ(certify_mesh3(m, o).rho_violations.count(), 1u);
  o.rho0.reset();
  m.metrics[3] = Sym3<Rational>{1, 0, 0, 4, 0, 9};
  m.metrics[0] = m.metrics[1] = m.metrics[2] = Sym3<Rational>{1, 0, 0, 1, 0, 1};
  o.gamma0 = 3;
  r = certify_mesh3(m, o);
  EXPECT_TRUE(r.gamma_violations.empty());
  EXPECT_NEAR(r.worst_gamma, 3, 1e-9);
  o.gamma0 = Rational(3) - Rational(1, 1000000000000);
  EXPECT_EQ(certify_mesh3(m, o).gamma_violations.count(), 1u);  // one witness per tetrahedron
  // A flat tetrahedron holds no bound vacuously (a reviewer's finding, with `valid` not asked):
  // its radius-edge ratio is unbounded and its dihedral angles are 0° and 180°; γ is the metrics'.
  m.vertices[3] = {1, 1, 0};
  o.rho0 = 100, o.gamma0 = 3, o.min_angle = 1, o.metric = true;
  r = certify_mesh3(m, o);
  EXPECT_EQ(r.rho_violations.count(), 1u);
  ASSERT_TRUE(r.angles.has_value());
  EXPECT_EQ(r.angles->violations.count(), 1u);
  EXPECT_TRUE(r.gamma_violations.empty());
  EXPECT_FALSE(r.holds(o));
}

// LU's sliver measure (oracle/certify/quasi_cosphericity.hpp). One Kuhn cube: its six tetrahedra
// turn around the main diagonal, six inner faces, and all eight corners lie on one sphere for
// M = I, so every configuration is exactly cospherical (γ* = 1) and, G ≠ 0, strictly
// γ₀-cospherical for every γ₀ > 1. Under the Delaunay metric (off-diagonals −¼) none is
// cospherical, and the exact count at γ₀ just below the least measured γ* is 0, just above it at
// least 1: the measure (eigenvalues in doubles) and the decision (polynomial signs) agree.
TEST(MeshCertifier3, SliverMeasureOfTheKuhnCube) {
  Certify3Options o;
  o.valid = false;
  o.gamma0 = Rational(1) + Rational(1, 1000000);
  const Certify3Report r = certify_mesh3(kuhn_grid(1, {1, 0, 0, 1, 0, 1}), o);
  ASSERT_TRUE(r.cosphericity.has_value());
  EXPECT_EQ(r.cosphericity->configurations, 6u);
  EXPECT_EQ(r.cosphericity->cospherical, 6u);
  EXPECT_EQ(r.cosphericity->least_critical, 1.0);
  EXPECT_EQ(r.cosphericity->quasi_cospherical, 6u);
  EXPECT_EQ(r.cosphericity->witnesses.count(), 6u);
  EXPECT_EQ(r.cosphericity->at_boundary, 0u);
  // Definition 3.9 by hand: every non-flat four of the five lies on the cube's sphere (radius
  // √3/2) and the shortest distance is an edge, 1: the ratio √3/2.
  EXPECT_NEAR(r.cosphericity->least_radius_edge, std::sqrt(3.0) / 2, 1e-12);

  const Rational q(-1, 4);
  const Mesh3 delaunay = kuhn_grid(2, {1, q, q, 1, q, 1});
  o.gamma0.reset();
  const Certify3Report d = certify_mesh3(delaunay, o);
  ASSERT_TRUE(d.cosphericity.has_value());
  EXPECT_EQ(d.cosphericity->cospherical, 0u);
  const double least = d.cosphericity->least_critical;
  ASSERT_GT(least, 1.0001);
  ASSERT_TRUE(std::isfinite(least));
  o.gamma0 = Rational(least * (1 - 1e-9));
  EXPECT_EQ(certify_mesh3(delaunay, o).cosphericity->quasi_cospherical, 0u);
  o.gamma0 = Rational(least * (1 + 1e-9));
  const Certify3Report above = certify_mesh3(delaunay, o);
  EXPECT_GE(above.cosphericity->quasi_cospherical, 1u);
  EXPECT_LT(above.cosphericity->quasi_cospherical, above.cosphericity->configurations);
  EXPECT_GT(above.cosphericity->least_radius_edge, 0.0);
  // Without the locally uniform check, no sliver measure.
  o.uniform = false;
  EXPECT_FALSE(certify_mesh3(delaunay, o).cosphericity.has_value());
}

// The five metrics of a configuration each asked (a second reader's finding: a boundary answer in
// the first vertex's metric hid a strict one in the next): two tetrahedra across the face of box
// corners (0,0,1), (0,2,0), (2,0,1), apexes (0,2,1) and (0,0,0); at γ₀ = 3/2 they are exactly at
// the boundary in vertex 0's metric (QuasiCospherical.AnExactTieIsTheBoundary) and, the five on
// one sphere, strictly cospherical in I, the other vertices' metric.
TEST(MeshCertifier3, SliverMeasureAsksEveryVertexMetric) {
  Mesh3 m;
  m.vertices = {{0, 0, 1}, {0, 2, 0}, {0, 2, 1}, {2, 0, 1}, {0, 0, 0}};
  m.tetrahedra = {{0, 1, 3, 2}, {0, 1, 3, 4}};
  const Sym3<Rational> tie{Rational(162, 227), 0, Rational(-65, 227), Rational(97, 227), Rational(65, 227), Rational(97, 227)};
  m.metrics = {tie, {1, 0, 0, 1, 0, 1}, {1, 0, 0, 1, 0, 1}, {1, 0, 0, 1, 0, 1}, {1, 0, 0, 1, 0, 1}};
  Certify3Options o;
  o.valid = false;
  o.gamma0 = Rational(3, 2);
  const Certify3Report r = certify_mesh3(m, o);
  ASSERT_TRUE(r.cosphericity.has_value());
  EXPECT_EQ(r.cosphericity->configurations, 1u);
  EXPECT_EQ(r.cosphericity->quasi_cospherical, 1u);
  EXPECT_EQ(r.cosphericity->at_boundary, 0u);
  EXPECT_EQ(r.cosphericity->cospherical, 1u);
  ASSERT_EQ(r.cosphericity->witnesses.count(), 1u);
  EXPECT_EQ(r.cosphericity->witnesses.places()[0].vertex, 1);  // the first metric that makes it strict
  EXPECT_EQ(r.cosphericity->witnesses.described()[0].text,
            "tetrahedra 0 and 1 (vertices 0 1 3 2 4) are γ₀-cospherical in the metric of vertex 1 (critical distortion about 1.000000, "
            "radius-edge ratio about 1.500000)");  // in I, by hand: all five on the 2 × 2 × 1 box's sphere, radius 3/2; shortest distance 1
  m.metrics.assign(5, tie);  // only the tied metric: the boundary
  const Certify3Report t = certify_mesh3(m, o);
  EXPECT_EQ(t.cosphericity->quasi_cospherical, 0u);
  EXPECT_EQ(t.cosphericity->at_boundary, 1u);
  EXPECT_EQ(t.cosphericity->cospherical, 0u);
}

namespace {

// A 2 × 2 × 2 Kuhn grid with every vertex moved at random and a random metric LLᵀ per vertex,
// all exact doubles (a binary file's numbers: the checks take their static-filter paths) or, with
// `tenths`, the same numbers divided by 10 (not doubles: the interval paths).
Mesh3 random_grid(std::mt19937& rng, bool tenths) {
  // Doubles with full mantissas: the double evaluations round, and only their bounds keep the
  // enclosures true.
  std::uniform_real_distribution<double> move(-0.15, 0.15), entry(-1, 1), diagonal(0.5, 1.5);
  Mesh3 m = anisocert::geometry::kuhn_grid(2);
  const auto moved = [&](const Rational& x) { return Rational(x.convert_to<double>() + move(rng)); };  // a double
  for (auto& p : m.vertices) p = {moved(p.x), moved(p.y), moved(p.z)};
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    // M = LLᵀ rounded to doubles entrywise: symmetric, positive definite (L is well conditioned).
    const double l1 = diagonal(rng), l2 = diagonal(rng), l3 = diagonal(rng), l21 = entry(rng) / 4, l31 = entry(rng) / 4, l32 = entry(rng) / 4;
    m.metrics.push_back({Rational(l1 * l1), Rational(l1 * l21), Rational(l1 * l31), Rational(l21 * l21 + l2 * l2), Rational(l21 * l31 + l2 * l32),
                         Rational(l31 * l31 + l32 * l32 + l3 * l3)});
  }
  if (tenths) {
    for (auto& p : m.vertices) p = {p.x / 10, p.y / 10, p.z / 10};
    for (auto& M : m.metrics) M = {100 * M.m11, 100 * M.m12, 100 * M.m13, 100 * M.m22, 100 * M.m23, 100 * M.m33};
  }
  return m;
}

}  // namespace

// Filters only speed up, never change, an answer: the static-bound enclosures of edge lengths and
// mean ratios (every input a double) and the interval ones (tenths) against rationals computed
// here. Unit edges are counted from ℓ² ∈ [1/2, 2] in both metrics; the least quality's enclosure
// [lo, hi] must hold the exact least: the exact decision q >= lo holds for every tetrahedron and
// q >= hi' (the next double above hi) fails for one.
TEST(MeshCertifier3, StaticAndIntervalEnclosuresHoldTheExactValues) {
  std::mt19937 rng(39);
  for (int round = 0; round < 30; ++round) {
    const Mesh3 m = random_grid(rng, round % 2 == 1);
    Certify3Options o = all_checks();
    o.valid = false, o.uniform = false;
    const Certify3Report r = certify_mesh3(m, o);
    ASSERT_TRUE(r.lengths && r.quality);
    std::vector<std::pair<int, int>> edges;
    for (const auto& t : m.tetrahedra)
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) edges.emplace_back(std::min(t[i], t[j]), std::max(t[i], t[j]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::size_t unit = 0;
    for (const auto& [a, b] : edges) {
      const auto d = minus(m.vertices[static_cast<std::size_t>(b)], m.vertices[static_cast<std::size_t>(a)]);
      const Rational la = form(m.metrics[static_cast<std::size_t>(a)], d), lb = form(m.metrics[static_cast<std::size_t>(b)], d);
      unit += la >= Rational(1, 2) && la <= 2 && lb >= Rational(1, 2) && lb <= 2;
    }
    EXPECT_EQ(r.lengths->unit_edges, unit) << "round " << round;
    const anisocert::FilterInterval worst = r.quality->worst;
    ASSERT_LE(worst.lo, worst.hi);
    Certify3Options q = o;
    q.metric = true;
    q.min_quality = Rational(worst.lo);
    EXPECT_TRUE(certify_mesh3(m, q).quality->violations.empty()) << "round " << round;
    q.min_quality = Rational(std::nextafter(worst.hi, 2.0));
    EXPECT_FALSE(certify_mesh3(m, q).quality->violations.empty()) << "round " << round;
  }
}

// The locally uniform search and the sliver measure run per tetrahedron and per face pair on every
// thread, the other checks beside them on a thread of their own; findings are added in order, so
// the report is the one thread's, witness for witness (with 5 described: the cap falls inside the
// lists). Meshes: the Kuhn grid under the +¼ metric (violations; γ₀ = 2 makes configurations
// γ₀-cospherical), under M = I (ties, exactly cospherical pairs), and randomly moved (random_grid).
TEST(MeshCertifier3, OneThreadAndSeveralGiveTheSameReport) {
  std::mt19937 rng(43);
  const Rational q(1, 4);
  for (const Mesh3& m : {kuhn_grid(4, {1, q, q, 1, q, 1}), kuhn_grid(3, {1, 0, 0, 1, 0, 1}), random_grid(rng, false), random_grid(rng, true)}) {
    Certify3Options o = all_checks();
    o.rho0 = 2, o.gamma0 = 2, o.min_quality = Rational(1, 2), o.min_angle = 30, o.described_witnesses = 5;
    o.threads = 1;
    const Certify3Report one = certify_mesh3(m, o);
    o.threads = 3;
    const Certify3Report three = certify_mesh3(m, o);
    expect_same_witnesses(one.uniform_violations, three.uniform_violations, "violations");
    expect_same_witnesses(one.uniform_ties, three.uniform_ties, "ties");
    expect_same_witnesses(one.rho_violations, three.rho_violations, "rho");
    expect_same_witnesses(one.gamma_violations, three.gamma_violations, "gamma");
    EXPECT_EQ(one.insphere_tests, three.insphere_tests);
    EXPECT_EQ(one.unmeasured, three.unmeasured);
    ASSERT_TRUE(one.cosphericity && three.cosphericity);
    const CosphericityReport &a = *one.cosphericity, &b = *three.cosphericity;
    EXPECT_EQ(a.configurations, b.configurations);
    EXPECT_EQ(a.cospherical, b.cospherical);
    EXPECT_EQ(a.quasi_cospherical, b.quasi_cospherical);
    EXPECT_EQ(a.at_boundary, b.at_boundary);
    EXPECT_EQ(a.unmeasured, b.unmeasured);
    EXPECT_EQ(a.least_critical, b.least_critical);
    EXPECT_EQ(a.least_tetrahedra[0], b.least_tetrahedra[0]);
    EXPECT_EQ(a.least_tetrahedra[1], b.least_tetrahedra[1]);
    EXPECT_EQ(a.least_radius_edge, b.least_radius_edge);
    expect_same_witnesses(a.witnesses, b.witnesses, "sliver witnesses");
    ASSERT_TRUE(one.valid && three.valid);
    EXPECT_EQ(one.valid->failure_count, three.valid->failure_count);
    ASSERT_TRUE(one.quality && three.quality && one.angles && three.angles);
    expect_same_witnesses(one.quality->violations, three.quality->violations, "quality");
    expect_same_witnesses(one.angles->violations, three.angles->violations, "angles");
  }
  // The cases are not vacuous: the first mesh has violations and γ₀-cospherical pairs, the second ties.
  Certify3Options o = all_checks();
  o.gamma0 = 2;
  EXPECT_GT(certify_mesh3(kuhn_grid(4, {1, q, q, 1, q, 1}), o).uniform_violations.count(), 5u);
  EXPECT_GT(certify_mesh3(kuhn_grid(4, {1, q, q, 1, q, 1}), o).cosphericity->witnesses.count(), 5u);
  EXPECT_GT(certify_mesh3(kuhn_grid(3, {1, 0, 0, 1, 0, 1}), o).uniform_ties.count(), 5u);
}
