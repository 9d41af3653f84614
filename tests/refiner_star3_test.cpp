// LU's stars in 3D (issue 40), their first pieces: the symbolically perturbed in-sphere test in a
// metric (predicates/insphere_perturbed.hpp) against the perturbed determinant evaluated at an
// explicit tiny ε in rationals, and the gift-wrapped star (refiners/star/gift_wrap3.hpp) against
// a brute-force star (every triple whose perturbed M-sphere is empty) on lattices, where five
// sites on one sphere are the rule, and on random sites; the stars of one metric must be
// consistent (LU Definition 3.3) and an interior site's link a closed sphere.
#include "predicates/insphere_perturbed.hpp"
#include "refiners/star/gift_wrap3.hpp"
#include "refiners/star/star_update3.hpp"

#include "rational_determinant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <set>

namespace {

using anisocert::Rational;
using anisocert::Sign;
using anisocert::predicates::Point3;
using anisocert::predicates::Sym3;
using anisocert::refiners::star::gift_wrap_star3;

using anisocert::testing::determinant;

Sign sign_of(const Rational& x) { return x > 0 ? Sign::positive : x < 0 ? Sign::negative : Sign::zero; }

Rational form(const Sym3<double>& M, const Point3<double>& p) {
  const Rational x(p.x), y(p.y), z(p.z);
  return Rational(M.m11) * x * x + Rational(M.m22) * y * y + Rational(M.m33) * z * z +
         2 * (Rational(M.m12) * x * y + Rational(M.m13) * x * z + Rational(M.m23) * y * z);
}

// The perturbed in-sphere value at ε_i = δ^(rank_i + 1), δ = 2⁻²⁰⁰, rank_i the position of site i
// among the five by increasing index: −det₅ [p, Q(p) + ε, 1]. With integer coordinates and metric
// (|P| ≥ 1 when P ≠ 0, each ε-coefficient an integer of at most a few thousand), δ is small
// enough for the first non-zero term to decide.
Sign explicit_perturbed(const std::array<Point3<double>, 5>& p, const std::array<int, 5>& index, const Sym3<double>& M) {
  std::array<int, 5> rank{};
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j) rank[i] += index[j] < index[i];
  Rational delta = 1;
  for (int k = 0; k < 200; ++k) delta /= 2;
  std::vector<std::vector<Rational>> rows;
  for (std::size_t i = 0; i < 5; ++i) {
    Rational eps = 1;
    for (int k = 0; k <= rank[i]; ++k) eps *= delta;
    rows.push_back({Rational(p[i].x), Rational(p[i].y), Rational(p[i].z), form(M, p[i]) + eps, Rational(1)});
  }
  return sign_of(-determinant(rows));
}

// An integer symmetric positive definite metric LLᵀ.
Sym3<double> random_metric(std::mt19937& rng) {
  std::uniform_int_distribution<int> diagonal(1, 3), off(-2, 2);
  const double l1 = diagonal(rng), l2 = diagonal(rng), l3 = diagonal(rng), l21 = off(rng), l31 = off(rng), l32 = off(rng);
  return {l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32, l31 * l31 + l32 * l32 + l3 * l3};
}

std::vector<Point3<double>> lattice(int n) {
  std::vector<Point3<double>> p;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y)
      for (int z = 0; z < n; ++z) p.push_back({double(x), double(y), double(z)});
  return p;
}

// (a, b, c) rotated to start at its least index: the same oriented triangle, one way.
std::array<int, 3> canonical(std::array<int, 3> t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// Every triple (a, b, c) with (v, a, b, c) positively oriented and no other site strictly inside
// its perturbed M-sphere.
std::set<std::array<int, 3>> brute_force_star(int v, const std::vector<Point3<double>>& p, const Sym3<double>& M) {
  std::set<std::array<int, 3>> star;
  const int n = static_cast<int>(p.size());
  const auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c) {
        if (a == v || b == v || c == v || a == b || a == c || b == c) continue;
        if (anisocert::predicates::orientation3(at(v), at(a), at(b), at(c)) != Sign::positive) continue;
        bool empty = true;
        for (int e = 0; e < n && empty; ++e)
          if (e != v && e != a && e != b && e != c)
            empty = anisocert::predicates::insphere_perturbed<double>({at(v), at(a), at(b), at(c), at(e)}, {v, a, b, c, e}, M) != Sign::positive;
        if (empty) star.insert(canonical({a, b, c}));
      }
  return star;
}

std::vector<int> all_but(int v, std::size_t n) {
  std::vector<int> c;
  for (int i = 0; i < static_cast<int>(n); ++i)
    if (i != v) c.push_back(i);
  return c;
}

}  // namespace

// Five sites of a 3 × 3 × 3 lattice (cube corners: many on one M-sphere for M = I or diagonal) or
// random integer sites, random indices, random metrics: the perturbed sign equals the explicit
// determinant's at a tiny ε, and is 0 only for five coplanar sites. Both signs of the
// perturbation's decision are seen, and many exact ties (the cases that need it).
TEST(InSpherePerturbed, IsTheDeterminantAtATinyExplicitEpsilon) {
  std::mt19937 rng(40);
  const auto grid = lattice(3);
  std::uniform_int_distribution<std::size_t> pick(0, grid.size() - 1);
  std::uniform_int_distribution<int> coordinate(-3, 3), index(0, 1000), kind(0, 3);
  std::size_t ties_positive = 0, ties_negative = 0, coplanar = 0;
  for (int round = 0; round < 10000; ++round) {
    std::array<Point3<double>, 5> p;
    const bool on_grid = round % 4 != 3;
    for (auto& q : p)
      q = on_grid ? grid[pick(rng)] : Point3<double>{double(coordinate(rng)), double(coordinate(rng)), double(coordinate(rng))};
    std::set<std::array<double, 3>> distinct;
    for (const auto& q : p) distinct.insert({q.x, q.y, q.z});
    if (distinct.size() < 5) continue;
    std::array<int, 5> idx;
    std::set<int> used;
    for (auto& i : idx) {
      do i = index(rng);
      while (!used.insert(i).second);
    }
    const int k = kind(rng);
    const Sym3<double> M = k == 0 ? Sym3<double>{1, 0, 0, 1, 0, 1} : k == 1 ? Sym3<double>{1, 0, 0, 4, 0, 9} : random_metric(rng);
    const Sign got = anisocert::predicates::insphere_perturbed<double>(p, idx, M);
    ASSERT_EQ(got, explicit_perturbed(p, idx, M)) << "round " << round;
    if (anisocert::predicates::insphere(p[0], p[1], p[2], p[3], p[4], M) == Sign::zero) {
      ties_positive += got == Sign::positive, ties_negative += got == Sign::negative, coplanar += got == Sign::zero;
    }
  }
  EXPECT_GT(ties_positive, 100u);
  EXPECT_GT(ties_negative, 100u);
  EXPECT_GT(coplanar, 10u);
}

// The gift-wrapped star of every site equals the brute-force one: on the 3 × 3 × 3 lattice (each
// unit cube's eight corners on one M-sphere for M = I and diagonal M) and on random sites, in
// random metrics. With one metric the stars are consistent: a tetrahedron in one site's star is in
// each of its vertices' stars (their union is the perturbed Delaunay tetrahedralization); the
// centre's link is a closed sphere (each link edge in two triangles, V − E + F = 2).
TEST(GiftWrapStar3, EqualsTheBruteForceStarAndStarsAreConsistent) {
  std::mt19937 rng(41);
  std::uniform_int_distribution<int> coordinate(-4, 4);
  for (int round = 0; round < 12; ++round) {
    std::vector<Point3<double>> p;
    if (round < 6) {
      p = lattice(3);
      std::shuffle(p.begin(), p.end(), rng);  // the indices, and so the perturbation's order
    } else {
      std::set<std::array<double, 3>> seen;
      while (p.size() < 24) {
        const Point3<double> q{double(coordinate(rng)), double(coordinate(rng)), double(coordinate(rng))};
        if (seen.insert({q.x, q.y, q.z}).second) p.push_back(q);
      }
    }
    const Sym3<double> M = round % 3 == 0 ? Sym3<double>{1, 0, 0, 1, 0, 1} : round % 3 == 1 ? Sym3<double>{1, 0, 0, 4, 0, 9} : random_metric(rng);
    std::map<std::array<int, 4>, int> tetrahedra;  // sorted vertices → the stars holding it
    for (int v = 0; v < static_cast<int>(p.size()); ++v) {
      const auto star = gift_wrap_star3(v, all_but(v, p.size()), p, M);
      std::set<std::array<int, 3>> wrapped;
      for (const auto& t : star.link) wrapped.insert(canonical(t));
      ASSERT_EQ(wrapped.size(), star.link.size()) << "a link triangle found twice, round " << round << ", site " << v;
      ASSERT_EQ(wrapped, brute_force_star(v, p, M)) << "round " << round << ", site " << v;
      for (const auto& t : star.link) {
        std::array<int, 4> s{v, t[0], t[1], t[2]};
        std::sort(s.begin(), s.end());
        ++tetrahedra[s];
      }
      const bool centre = round < 6 && p[static_cast<std::size_t>(v)].x == 1 && p[static_cast<std::size_t>(v)].y == 1 && p[static_cast<std::size_t>(v)].z == 1;
      if (centre) {
        EXPECT_TRUE(star.open.empty());
        std::set<std::pair<int, int>> edges;
        std::set<int> vertices;
        for (const auto& t : star.link)
          for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
            edges.insert({std::min(a, b), std::max(a, b)}), vertices.insert(a);
            EXPECT_EQ(std::count_if(star.link.begin(), star.link.end(),
                                    [&](const std::array<int, 3>& u) {
                                      return (u[0] == b && u[1] == a) || (u[1] == b && u[2] == a) || (u[2] == b && u[0] == a);
                                    }),
                      1);
          }
        EXPECT_EQ(static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) + static_cast<long>(star.link.size()), 2);
      }
    }
    for (const auto& [t, count] : tetrahedra) EXPECT_EQ(count, 4) << "round " << round << ": a tetrahedron in " << count << " of its 4 stars";
  }
}

// LU Lemma 3.5 in 3D: a star's conflict zone (the union of its tetrahedra's M-spheres) does not
// grow when a site is inserted. Random integer sites and metrics, a random new site (it changes
// the star in some rounds: counted); probes on a half-integer grid of the sites' box: a probe strictly inside a new sphere is inside or on an old one (exact tests). The
// star's site is the origin, inside the hull of the box's corners, so that its star is closed.
TEST(GiftWrapStar3, ConflictZoneDoesNotGrowUnderInsertion) {
  std::mt19937 rng(35);
  std::uniform_int_distribution<int> coordinate(-4, 4);
  std::size_t changed = 0, probes_inside = 0;
  const auto inside = [](const std::vector<Point3<double>>& p, int v, const std::array<int, 3>& t, const Point3<double>& q, const Sym3<double>& M) {
    const auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
    return anisocert::predicates::insphere(at(v), at(t[0]), at(t[1]), at(t[2]), q, M);  // positive: strictly inside
  };
  for (int round = 0; round < 30; ++round) {
    std::vector<Point3<double>> p;
    std::set<std::array<double, 3>> seen;
    const auto fresh = [&] {
      while (true) {
        const Point3<double> q{double(coordinate(rng)), double(coordinate(rng)), double(coordinate(rng))};
        if (seen.insert({q.x, q.y, q.z}).second) return q;
      }
    };
    // v = the origin, inside the hull of the box's corners (±5): its star is closed.
    p.push_back({0, 0, 0}), seen.insert({0, 0, 0});
    for (int k = 0; k < 8; ++k) p.push_back({k & 1 ? 5.0 : -5.0, k & 2 ? 5.0 : -5.0, k & 4 ? 5.0 : -5.0});
    while (p.size() < 24) p.push_back(fresh());
    const Sym3<double> M = round % 2 == 0 ? Sym3<double>{1, 0, 0, 1, 0, 1} : random_metric(rng);
    const int v = 0;
    const auto before = gift_wrap_star3(v, all_but(v, p.size()), p, M);
    p.push_back(fresh());
    const auto after = gift_wrap_star3(v, all_but(v, p.size()), p, M);
    ASSERT_TRUE(before.open.empty() && after.open.empty());
    std::set<std::array<int, 3>> b, a;
    for (const auto& t : before.link) b.insert(canonical(t));
    for (const auto& t : after.link) a.insert(canonical(t));
    changed += a != b;
    for (int x = -8; x <= 8; ++x)
      for (int y = -8; y <= 8; ++y)
        for (int z = -8; z <= 8; ++z) {
          const Point3<double> q{x / 2.0, y / 2.0, z / 2.0};
          const bool in_new = std::any_of(after.link.begin(), after.link.end(), [&](const auto& t) { return inside(p, v, t, q, M) == Sign::positive; });
          if (!in_new) continue;
          ++probes_inside;
          EXPECT_TRUE(std::any_of(before.link.begin(), before.link.end(), [&](const auto& t) { return inside(p, v, t, q, M) != Sign::negative; }))
              << "round " << round << ": probe (" << q.x << ", " << q.y << ", " << q.z << ") is in the new conflict zone only";
        }
  }
  EXPECT_GT(changed, 5u);  // insertions that changed the star
  EXPECT_GT(probes_inside, 1000u);
}

// Stars kept by insertion (Bowyer–Watson restricted to each star, refiners/star/star_update3.hpp)
// equal the stars wrapped from scratch after every insertion: sites added one by one to a box's
// corners, on the integer lattice (cospherical fives: the perturbation decides), inside the box
// and on its faces (coplanar with the open faces of the stars on the hull: the ghosts' rule), in
// I, diag(1, 4, 9) and random metrics. The links and the open faces are compared; updates that ask
// to wrap again are rare (counted).
TEST(StarUpdate3, InsertionGivesTheWrappedStar) {
  using anisocert::refiners::star::insert_into_star3;
  using anisocert::refiners::star::Star3;
  using anisocert::refiners::star::Star3Update;
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> coordinate(-3, 3);
  std::size_t updated = 0, recomputed = 0, unchanged = 0;
  const auto same = [](const Star3& x, const Star3& y) {
    std::set<std::array<int, 3>> a, b;
    for (const auto& t : x.link) a.insert(canonical(t));
    for (const auto& t : y.link) b.insert(canonical(t));
    std::set<std::array<int, 2>> oa(x.open.begin(), x.open.end()), ob(y.open.begin(), y.open.end());
    return a == b && a.size() == x.link.size() && oa == ob && oa.size() == x.open.size();
  };
  std::uniform_int_distribution<int> axis(0, 5);
  std::size_t on_faces = 0;
  for (int round = 0; round < 9; ++round) {
    const Sym3<double> M = round % 3 == 0 ? Sym3<double>{1, 0, 0, 1, 0, 1} : round % 3 == 1 ? Sym3<double>{1, 0, 0, 4, 0, 9} : random_metric(rng);
    std::vector<Point3<double>> p;
    std::set<std::array<double, 3>> seen;
    for (int k = 0; k < 8; ++k) {
      p.push_back({k & 1 ? 4.0 : -4.0, k & 2 ? 4.0 : -4.0, k & 4 ? 4.0 : -4.0});
      seen.insert({p.back().x, p.back().y, p.back().z});
    }
    std::vector<Star3> stars;
    for (int v = 0; v < 8; ++v) stars.push_back(gift_wrap_star3(v, all_but(v, p.size()), p, M));
    for (int step = 0; step < 40; ++step) {
      Point3<double> q;
      const int face = step % 2 ? axis(rng) : -1;  // every other site on a face of the box
      do {
        q = {double(coordinate(rng)), double(coordinate(rng)), double(coordinate(rng))};
        if (face >= 0) (face % 3 == 0 ? q.x : face % 3 == 1 ? q.y : q.z) = face < 3 ? -4 : 4;
      } while (!seen.insert({q.x, q.y, q.z}).second);
      on_faces += face >= 0;
      p.push_back(q);
      const int k = static_cast<int>(p.size()) - 1;
      for (int v = 0; v < k; ++v) {
        Star3& s = stars[static_cast<std::size_t>(v)];
        const Star3Update u = insert_into_star3(s, v, k, p, M);
        const Star3 wrapped = gift_wrap_star3(v, all_but(v, p.size()), p, M);
        if (u == Star3Update::recompute) s = wrapped;
        updated += u == Star3Update::updated, recomputed += u == Star3Update::recompute, unchanged += u == Star3Update::unchanged;
        ASSERT_TRUE(same(s, wrapped)) << "round " << round << ", step " << step << ", star of " << v;
      }
      stars.push_back(gift_wrap_star3(k, all_but(k, p.size()), p, M));
    }
  }
  EXPECT_GT(updated, 1000u);
  EXPECT_GT(unchanged, 1000u);
  EXPECT_GT(on_faces, 150u);
  EXPECT_LT(recomputed, updated / 50);
}
