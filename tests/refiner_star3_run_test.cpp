// The 3D star refiner (issue 40) and what it stands on, against independent computations:
//  - Domain3's exact side of a point (ray parity) against the cube's and the cube-cylinder's
//    definitions in rationals (inside the box and outside the arc's polygon, decided by the
//    test's own determinants), on random dyadic points and on points exactly on the facets;
//  - the built-in polyhedra are solids (polyhedron_defect) of the volume their definition gives
//    (the cube 1; the cube-cylinder 1 minus the area of the arc's polygon, by the shoelace
//    formula here);
//  - a finished run on the cube with constant fields (isotropic, anisotropic and rotated): stars
//    consistent, the certifier certifies the mesh (valid, locally uniform, ρ₀ and γ₀), the
//    tetrahedra fill the cube (their exact volumes sum to 1, each positive), every vertex is in
//    the closed cube and every boundary face lies in a face of it, every tetrahedron's M_v-sphere
//    holds no vertex strictly inside by the test's own rational 5 × 5 determinant, and the
//    tetrahedra at each vertex v are exactly v's star wrapped from scratch among all the vertices
//    (the brute-force star the incremental stars must equal).
#include "geometry/builtin_polyhedra.hpp"
#include "oracle/certify/mesh_certifier3.hpp"
#include "predicates/orientation3.hpp"
#include "refiners/common/boundary3.hpp"
#include "refiners/common/domain3.hpp"
#include "refiners/star/gift_wrap3.hpp"
#include "refiners/star/pick_valid3.hpp"
#include "refiners/star/star_refiner3.hpp"

#include "rational_determinant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <variant>

namespace {

using anisocert::Rational;
using anisocert::rational_from_double;
using anisocert::predicates::Point3;
using anisocert::predicates::Sym3;
namespace common = anisocert::refiners::common;
using anisocert::geometry::Polyhedron;

Rational R(double d) { return rational_from_double(d); }

using anisocert::testing::determinant;

// Rational vectors, and metrics M = FᵀF for integer upper-triangular F (the tests' own algebra).
using Vec3 = std::array<Rational, 3>;
using IntMatrix3 = std::array<std::array<int, 3>, 3>;

Vec3 image(const IntMatrix3& F, const Point3<double>& q) {  // F q in rationals
  const Vec3 p{R(q.x), R(q.y), R(q.z)};
  Vec3 y{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) y[i] += Rational(F[i][k]) * p[k];
  return y;
}
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Rational dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Sym3<double> metric_of(const IntMatrix3& F) {  // FᵀF, exact in doubles (small integers)
  double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      m[i][j] = 0;
      for (int k = 0; k < 3; ++k) m[i][j] += F[k][i] * F[k][j];
    }
  return {m[0][0], m[0][1], m[0][2], m[1][1], m[1][2], m[2][2]};
}

Rational volume6(const Point3<double>& a, const Point3<double>& b, const Point3<double>& c, const Point3<double>& d) {
  return determinant({{R(b.x) - R(a.x), R(b.y) - R(a.y), R(b.z) - R(a.z)},
                      {R(c.x) - R(a.x), R(c.y) - R(a.y), R(c.z) - R(a.z)},
                      {R(d.x) - R(a.x), R(d.y) - R(a.y), R(d.z) - R(a.z)}});
}

// The arc's polygon of the cube-cylinder in the plane: its points from (0.5, 0) to (0, 0.5) and the
// origin, counter-clockwise; (x, y) is strictly inside it when strictly left of every edge.
std::vector<std::array<Rational, 2>> arc_polygon(const anisocert::geometry::Polyhedron& p) {
  std::vector<std::array<Rational, 2>> poly{{Rational(0), Rational(0)}};
  for (const auto& v : p.vertices)
    if (v.z == 0 && (v.x * v.x + v.y * v.y) * 4 <= Rational(101, 100) && !(v.x == 0 && v.y == 0)) poly.push_back({v.x, v.y});
  // The arc's points by angle: by decreasing x.
  std::sort(poly.begin() + 1, poly.end(), [](const auto& a, const auto& b) { return a[0] > b[0]; });
  return poly;
}

Rational cross(const std::array<Rational, 2>& o, const std::array<Rational, 2>& a, const Rational& x, const Rational& y) {
  return (a[0] - o[0]) * (y - o[1]) - (a[1] - o[1]) * (x - o[0]);
}

}  // namespace

TEST(Domain3, SideIsTheCubesAndTheCubeCylindersDefinition) {
  const auto cube = anisocert::geometry::cube_polyhedron();
  const auto cc = anisocert::geometry::cube_cylinder_polyhedron();
  ASSERT_FALSE(anisocert::geometry::polyhedron_defect(cube));
  ASSERT_FALSE(anisocert::geometry::polyhedron_defect(cc));
  const common::Domain3 dcube(cube), dcc(cc);
  EXPECT_TRUE(dcube.convex());
  EXPECT_FALSE(dcc.convex());
  const auto poly = arc_polygon(cc);
  ASSERT_EQ(poly.size(), 18u);  // the origin and the 17 points of 16 strips
  // Exact volumes: the cube's tetrahedra from a centre, the cube-cylinder's likewise.
  const auto volume = [](const anisocert::geometry::Polyhedron& p) {
    Rational v = 0;
    for (const auto& t : p.facets) {
      const auto &a = p.vertices[t[0]], &b = p.vertices[t[1]], &c = p.vertices[t[2]];
      v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
    }
    return v / 6;
  };
  EXPECT_EQ(volume(cube), 1);
  Rational area = 0;  // the arc polygon's, by the shoelace formula
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto &a = poly[i], &b = poly[(i + 1) % poly.size()];
    area += a[0] * b[1] - a[1] * b[0];
  }
  EXPECT_EQ(volume(cc), 1 - area / 2);
  std::mt19937 rng(40);
  std::uniform_int_distribution<int> coordinate(-8, 72);  // k / 64: outside, on and inside [0, 1]
  std::size_t seen[2][3] = {};
  for (int n = 0; n < 4000; ++n) {
    const Point3<double> q{coordinate(rng) / 64.0, coordinate(rng) / 64.0, coordinate(rng) / 64.0};
    const Rational x = R(q.x), y = R(q.y), z = R(q.z);
    const bool in_box = x >= 0 && x <= 1 && y >= 0 && y <= 1 && z >= 0 && z <= 1;
    const bool interior_box = x > 0 && x < 1 && y > 0 && y < 1 && z > 0 && z < 1;
    const auto cube_side = !in_box ? common::Side::outside : interior_box ? common::Side::inside : common::Side::boundary;
    EXPECT_EQ(dcube.side(q), cube_side) << q.x << " " << q.y << " " << q.z;
    ++seen[0][static_cast<int>(cube_side)];
    // The cube-cylinder: the box minus the open prism over the arc polygon (convex: strictly left
    // of every edge is inside it; on an edge of it, with x, y ≥ 0, is on the curved face).
    // The polygon's edges: origin → arc → origin; the first and the last are not the solid's (its
    // points with x, y < 0.5 on them are in the hole), the arc's are the curved face.
    int left = 0, on = 0;
    bool on_arc = false;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Rational s = cross(poly[i], poly[(i + 1) % poly.size()], x, y);
      left += s > 0, on += s == 0;
      on_arc = on_arc || (s == 0 && i >= 1 && i + 1 < poly.size());
    }
    const bool in_closed_prism = left + on == static_cast<int>(poly.size());
    const bool in_prism = left == static_cast<int>(poly.size());
    const auto cc_side = !in_box || in_prism || (in_closed_prism && !on_arc) ? common::Side::outside
                         : in_closed_prism || !interior_box                 ? common::Side::boundary
                                                                             : common::Side::inside;
    EXPECT_EQ(dcc.side(q), cc_side) << q.x << " " << q.y << " " << q.z;
    ++seen[1][static_cast<int>(cc_side)];
  }
  for (const auto& s : seen)
    for (std::size_t k : s) EXPECT_GT(k, 100u);  // inside, on the boundary and outside, each often
}

// A finished run on the cube, checked independently (see the head of this file).
TEST(StarRefiner3, CubeRunsAreCertifiedAndEqualTheBruteForceStars) {
  const common::Domain3 cube(anisocert::geometry::cube_polyhedron());
  // Isotropic, axis-anisotropic, and rotated (LLᵀ with L lower triangular, integers).
  const std::vector<Sym3<double>> metrics{{16, 0, 0, 16, 0, 16}, {9, 0, 0, 16, 0, 36}, {9, 6, 3, 20, 4, 11}};
  for (const Sym3<double>& M : metrics) {
    anisocert::fields::MetricField3 field{"constant", {}, [M](double, double, double) { return M; }};
    anisocert::refiners::star::RefineParameters p;
    p.max_seconds = 60;
    const auto r = anisocert::refiners::star::refine_star3(cube, field, p);
    ASSERT_TRUE(r.consistent) << r.stop_reason;
    EXPECT_EQ(r.faces_off_boundary, 0u);
    const auto& m = r.mesh;
    ASSERT_GT(m.vertices.size(), 50u);
    // The certifier.
    anisocert::geometry::Mesh3<Rational> exact;
    for (const auto& q : m.vertices) exact.vertices.push_back({R(q.x), R(q.y), R(q.z)});
    for (const auto& N : m.metrics) exact.metrics.push_back({R(N.m11), R(N.m12), R(N.m13), R(N.m22), R(N.m23), R(N.m33)});
    exact.tetrahedra = m.tetrahedra, exact.triangles = m.triangles;
    anisocert::oracle::Certify3Options o;
    o.rho0 = R(p.rho0), o.gamma0 = R(p.gamma0), o.threads = 1;
    const auto report = anisocert::oracle::certify_mesh3(exact, o);
    EXPECT_TRUE(report.holds(o));
    // The tetrahedra fill the cube.
    Rational total = 0;
    for (const auto& t : m.tetrahedra) {
      const Rational v = volume6(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]);
      EXPECT_GT(v, 0);
      total += v;
    }
    EXPECT_EQ(total, 6);
    for (const auto& q : m.vertices) EXPECT_NE(cube.side(q), common::Side::outside);
    for (const auto& f : m.triangles) {
      const auto &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
      const bool on_a_face = (a.x == b.x && b.x == c.x && (a.x == 0 || a.x == 1)) || (a.y == b.y && b.y == c.y && (a.y == 0 || a.y == 1)) ||
                             (a.z == b.z && b.z == c.z && (a.z == 0 || a.z == 1));
      EXPECT_TRUE(on_a_face);
    }
    // Local uniformity by the test's own determinant, and the stars from scratch.
    std::map<int, std::set<std::array<int, 3>>> at_vertex;  // v → its tetrahedra's other vertices, sorted
    for (const auto& t : m.tetrahedra)
      for (int i = 0; i < 4; ++i) {
        std::array<int, 3> o3;
        for (int j = 0, k = 0; j < 4; ++j)
          if (j != i) o3[k++] = t[j];
        std::sort(o3.begin(), o3.end());
        at_vertex[t[i]].insert(o3);
      }
    const auto Q = [&](const Sym3<double>& N, const Point3<double>& q) {
      const Rational x = R(q.x), y = R(q.y), z = R(q.z);
      return R(N.m11) * x * x + R(N.m22) * y * y + R(N.m33) * z * z + 2 * (R(N.m12) * x * y + R(N.m13) * x * z + R(N.m23) * y * z);
    };
    const int n = static_cast<int>(m.vertices.size());
    std::size_t checked = 0;
    for (int v = 0; v < n; v += 3) {  // a third of the vertices: all their tetrahedra against all vertices
      const auto& N = m.metrics[v];
      for (const auto& o3 : at_vertex[v]) {
        std::array<int, 4> t{v, o3[0], o3[1], o3[2]};
        const Rational orient = volume6(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]);
        for (int e = 0; e < n; ++e) {
          if (std::find(t.begin(), t.end(), e) != t.end()) continue;
          std::vector<std::vector<Rational>> rows;
          for (int w : {t[0], t[1], t[2], t[3], e})
            rows.push_back({R(m.vertices[w].x), R(m.vertices[w].y), R(m.vertices[w].z), Q(N, m.vertices[w]), Rational(1)});
          // e strictly inside the M_v-sphere of t: −det₅ has the sign of t's orientation.
          const Rational in = -determinant(rows) * (orient > 0 ? 1 : -1);
          EXPECT_LE(in, 0) << "vertex " << e << " inside the sphere of a tetrahedron at " << v;
          ++checked;
        }
      }
      std::vector<int> others;
      for (int w = 0; w < n; ++w)
        if (w != v) others.push_back(w);
      const auto star = anisocert::refiners::star::gift_wrap_star3(v, others, m.vertices, N);
      std::set<std::array<int, 3>> wrapped;
      for (auto t : star.link) {
        std::sort(t.begin(), t.end());
        wrapped.insert(t);
      }
      EXPECT_EQ(wrapped, at_vertex[v]) << "the mesh's tetrahedra at " << v << " are not its star among all vertices";
    }
    EXPECT_GT(checked, 10000u);
  }
}

// LU Lemma 4.1 in 3D, its hypothesis (issue 40): Ω's ridges whose interior dihedral angle is not
// above 90° in the metric (Boundary3::ridge_angles: outward normals and adj(M), exactly) against
// an independent computation: with M = FᵀF (F an integer upper-triangular matrix), the angle at a
// ridge ab between facets abc and abd is the Euclidean one after x ↦ Fx, above 90° iff the
// components of c − a and d − a perpendicular to b − a have a negative dot product (rationals);
// reflex ridges (the far vertex beyond the other facet's plane) are above 180°. On the cube (every
// ridge exactly 90° under diagonal metrics, so none obtuse) and a prism over an octagon with 135°
// corners (its 8 vertical ridges obtuse under I, its 16 horizontal ones right), under I, diagonal
// and random sheared metrics; both answers seen.
TEST(Boundary3, RidgeAnglesAreTheTransformedEuclideanAngles) {
  using anisocert::geometry::Polyhedron;
  // The octagon (1,0) (2,0) (3,1) (3,2) (2,3) (1,3) (0,2) (0,1), counter-clockwise, as a prism of height 1.
  Polyhedron octagon;
  const int ring[8][2] = {{1, 0}, {2, 0}, {3, 1}, {3, 2}, {2, 3}, {1, 3}, {0, 2}, {0, 1}};
  for (int z = 0; z < 2; ++z)
    for (const auto& p : ring) octagon.vertices.push_back({Rational(p[0]), Rational(p[1]), Rational(z)});
  for (int i = 1; i + 1 < 8; ++i) octagon.facets.push_back({0, i + 1, i}), octagon.facets.push_back({8, 8 + i, 8 + i + 1});
  for (int i = 0; i < 8; ++i) {
    const int j = (i + 1) % 8;
    octagon.facets.push_back({i, j, 8 + j}), octagon.facets.push_back({i, 8 + j, 8 + i});
  }
  ASSERT_FALSE(anisocert::geometry::polyhedron_defect(octagon));
  std::mt19937 rng(41);
  std::uniform_int_distribution<int> diagonal(1, 4), off(-3, 3);
  std::size_t obtuse = 0, not_obtuse = 0;
  for (const Polyhedron& shape : {anisocert::geometry::cube_polyhedron(), octagon}) {
    const common::Domain3 domain(shape);
    for (int round = 0; round < 12; ++round) {
      // F upper triangular: I, then diagonal, then sheared.
      IntMatrix3 F{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
      if (round > 0) F = {{{diagonal(rng), 0, 0}, {0, diagonal(rng), 0}, {0, 0, diagonal(rng)}}};
      if (round > 3) F[0][1] = off(rng), F[0][2] = off(rng), F[1][2] = off(rng);
      const Sym3<double> M = metric_of(F);
      anisocert::fields::MetricField3 field{"constant", {}, [M](double, double, double) { return M; }};
      common::Sites3 sites(domain, field);
      for (const auto& q : domain.vertices()) sites.add(q, M);
      sites.grow_grid();
      const common::Boundary3 boundary(domain, sites);
      const auto angles = boundary.ridge_angles();
      // The brute force over the facets' edges.
      const auto& x = domain.vertices();
      const auto Fx = [&](int v) { return image(F, x[v]); };
      std::map<std::array<int, 2>, std::vector<int>> at;
      const auto& facets = domain.facets();
      for (int f = 0; f < static_cast<int>(facets.size()); ++f)
        for (int e = 0; e < 3; ++e) at[{std::min(facets[f][e], facets[f][(e + 1) % 3]), std::max(facets[f][e], facets[f][(e + 1) % 3])}].push_back(f);
      std::size_t ridges = 0;
      std::vector<std::array<int, 2>> expected;
      for (const auto& entry : at) {
        const std::array<int, 2>& e = entry.first;
        const std::vector<int>& fs = entry.second;
        if (domain.coplanar(fs[0], fs[1])) continue;
        ++ridges;
        const auto third = [&](int f) {
          for (int k : facets[f])
            if (k != e[0] && k != e[1]) return k;
          return -1;
        };
        const int c = third(fs[0]), d = third(fs[1]);
        const auto& tf = facets[fs[0]];
        if (anisocert::predicates::orientation3(x[tf[0]], x[tf[1]], x[tf[2]], x[d]) == anisocert::Sign::positive) continue;  // reflex
        const auto t = minus(Fx(e[1]), Fx(e[0])), u = minus(Fx(c), Fx(e[0])), w = minus(Fx(d), Fx(e[0]));
        const Rational s = dot(u, w) * dot(t, t) - dot(u, t) * dot(w, t);  // |t|² (u⊥ · w⊥)
        if (s >= 0) expected.push_back(e);
      }
      EXPECT_EQ(angles.ridges, ridges);
      EXPECT_EQ(angles.not_obtuse, expected) << "round " << round;
      not_obtuse += expected.size(), obtuse += ridges - expected.size();
    }
  }
  EXPECT_GT(obtuse, 50u);
  EXPECT_GT(not_obtuse, 50u);
}

// The surface level's LEPP–Delaunay splits (Boundary3::split, then Lawson's flips in the new
// site's metric): under a constant metric M = FᵀF (F integer upper triangular, sheared), after
// 300 splits of random subfacet edges at their midpoints every edge between two subfacets in one
// plane is locally Delaunay in M: the far apex is not strictly inside the circumcircle of the
// other subfacet after x ↦ Fx, its centre solved here in rationals (Cramer, the test's own
// determinant). Bisection alone breaks it under a sheared metric (the cascade of thin subfacets
// that made UGAWG's linear field at h0 = 0.05 refine the cube's faces to 10⁻⁷, regression
// `CliRefine3.UgawgLinearAtH0_005IsCertified`); the subfacets also tile each face (their exact
// areas in the face sum to 1), and the edge Insert_or_snap splits for a point just inside a face
// is LEPP's terminal edge in M's lengths.
TEST(Boundary3, SplitsKeepEachPlaneDelaunayInAConstantMetric) {
  const common::Domain3 domain(anisocert::geometry::cube_polyhedron());
  std::mt19937 rng(40);
  std::uniform_int_distribution<int> diagonal(1, 4), off(-3, 3);
  std::size_t checked = 0, lepp_checked = 0;
  for (int round = 0; round < 4; ++round) {
    const IntMatrix3 F{{{diagonal(rng), off(rng), off(rng)}, {0, diagonal(rng), off(rng)}, {0, 0, diagonal(rng)}}};
    const Sym3<double> M = metric_of(F);
    anisocert::fields::MetricField3 field{"constant", {}, [M](double, double, double) { return M; }};
    common::Sites3 sites(domain, field);
    for (const auto& q : domain.vertices()) sites.add(q, M);
    sites.grow_grid();
    common::Boundary3 boundary(domain, sites);
    for (int split = 0; split < 300; ++split) {
      const auto faces = boundary.subfacets();
      const auto& f = faces[std::uniform_int_distribution<std::size_t>(0, faces.size() - 1)(rng)];
      const int e = std::uniform_int_distribution<int>(0, 2)(rng);
      const common::Boundary3::Edge edge{std::min(f[e], f[(e + 1) % 3]), std::max(f[e], f[(e + 1) % 3])};
      const auto mid = boundary.midpoint(edge);
      ASSERT_TRUE(std::holds_alternative<Point3<double>>(mid));
      const int k = sites.add(std::get<Point3<double>>(mid), M);
      if (sites.grow_grid()) boundary.refile();
      boundary.split(edge, k);
      boundary.site_added(k);
    }
    const auto Fx = [&](int v) { return image(F, sites.points[v]); };
    const auto faces = boundary.subfacets();
    std::map<std::array<int, 2>, std::vector<int>> at;
    for (int t = 0; t < static_cast<int>(faces.size()); ++t)
      for (int e = 0; e < 3; ++e) at[{std::min(faces[t][e], faces[t][(e + 1) % 3]), std::max(faces[t][e], faces[t][(e + 1) % 3])}].push_back(t);
    for (const auto& entry : at) {
      const std::array<int, 2>& e = entry.first;
      const std::vector<int>& ts = entry.second;
      ASSERT_EQ(ts.size(), 2u) << "the subfacets are a closed surface";
      const auto apex = [&](int t) {
        for (int w : faces[t])
          if (w != e[0] && w != e[1]) return w;
        return -1;
      };
      const int c = apex(ts[0]), d = apex(ts[1]);
      const auto& x = sites.points;
      if (anisocert::predicates::orientation3(x[e[0]], x[e[1]], x[c], x[d]) != anisocert::Sign::zero) continue;  // a ridge
      // The circumcentre o of Fa, Fb, Fc: (o − a)·u = |u|²/2, (o − a)·v = |v|²/2, (o − a)·n = 0.
      const auto a = Fx(e[0]), u = minus(Fx(e[1]), a), v = minus(Fx(c), a);
      const std::array<Rational, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const std::vector<std::vector<Rational>> A{{u[0], u[1], u[2]}, {v[0], v[1], v[2]}, {n[0], n[1], n[2]}};
      const std::array<Rational, 3> rhs{dot(u, u) / 2, dot(v, v) / 2, Rational(0)};
      const Rational det = determinant(A);
      std::array<Rational, 3> o{};
      for (int j = 0; j < 3; ++j) {
        auto Aj = A;
        for (int i = 0; i < 3; ++i) Aj[i][j] = rhs[i];
        o[j] = determinant(Aj) / det;
      }
      const auto w = minus(Fx(d), a);
      EXPECT_GE(dot(minus(w, o), minus(w, o)), dot(o, o)) << "edge " << e[0] << "-" << e[1] << " is not Delaunay in M, round " << round;
      ++checked;
    }
    // The subfacets tile the six faces: in each face the doubled areas |(b − a) × (c − a)| sum to 2.
    std::map<std::pair<int, double>, Rational> area;  // (axis, side) → doubled area
    for (const auto& t : faces) {
      const auto& x = sites.points;
      const auto coord = [&](int w, int i) { return i == 0 ? x[w].x : i == 1 ? x[w].y : x[w].z; };
      int axis = 0;
      while (!(coord(t[0], axis) == coord(t[1], axis) && coord(t[0], axis) == coord(t[2], axis))) ++axis;
      const auto p = [&](int w) { return std::array<Rational, 3>{R(x[w].x), R(x[w].y), R(x[w].z)}; };
      const auto b = minus(p(t[1]), p(t[0])), c = minus(p(t[2]), p(t[0]));
      const Rational cr = b[(axis + 1) % 3] * c[(axis + 2) % 3] - b[(axis + 2) % 3] * c[(axis + 1) % 3];
      area[{axis, coord(t[0], axis)}] += cr < 0 ? -cr : cr;
    }
    ASSERT_EQ(area.size(), 6u);
    for (const auto& [face, doubled] : area) EXPECT_EQ(doubled, Rational(2));
    // LEPP's order: a point just inside a face, away from its ridges, encroaches subfacets there;
    // the edge Insert_or_snap splits for it, unless a ridge, is the longest in M (uᵀMu in
    // rationals) of both subfacets holding it (Rivara's terminal edge), not the longest in
    // Euclidean length (a mutant ordering by Euclidean length fails here).
    for (int probe = 0; probe < 40; ++probe) {
      std::uniform_real_distribution<double> middle(0.25, 0.75), depth(0.001, 0.01);
      const int axis = probe % 3;
      std::array<double, 3> c{middle(rng), middle(rng), middle(rng)};
      c[axis] = probe % 2 ? depth(rng) : 1 - depth(rng);
      const auto edge = boundary.snap({c[0], c[1], c[2]}, M, M);
      ASSERT_TRUE(edge) << "a point 0.01 inside a face encroaches no subfacet";
      std::vector<std::array<int, 3>> holding;
      for (const auto& t : faces)
        if (std::count(t.begin(), t.end(), (*edge)[0]) && std::count(t.begin(), t.end(), (*edge)[1])) holding.push_back(t);
      ASSERT_EQ(holding.size(), 2u);
      const auto& x = sites.points;
      const int c0 = holding[0][0] + holding[0][1] + holding[0][2] - (*edge)[0] - (*edge)[1];
      const int c1 = holding[1][0] + holding[1][1] + holding[1][2] - (*edge)[0] - (*edge)[1];
      if (anisocert::predicates::orientation3(x[(*edge)[0]], x[(*edge)[1]], x[c0], x[c1]) != anisocert::Sign::zero) continue;  // a ridge
      const auto length2 = [&](int a, int b) {
        const auto u = minus(Fx(b), Fx(a));
        return dot(u, u);  // (b − a)ᵀ M (b − a)
      };
      const Rational e2 = length2((*edge)[0], (*edge)[1]);
      for (const auto& t : holding)
        for (int i = 0; i < 3; ++i) EXPECT_LE(length2(t[i], t[(i + 1) % 3]), e2) << "round " << round << ", probe " << probe;
      ++lepp_checked;
    }
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_GE(lepp_checked, 4u);
}

// Pick_valid in 3D (LU Definitions 3.6 and 3.9; refiners/star/pick_valid3.hpp): the picking region
// (δ = 10⁻⁶) of a sphere centred at X = 0, with four sites p, q, r, s on the sphere of radius 1/2
// through X (centre (1/2, 0, 0)): every point picked makes a new tetrahedron xpqr with s
// cospherical up to 10⁻⁶, γ₀-cospherical for γ₀ = 1.01, with radius 1/2 < β r_τ and radius-edge
// ratio below ρ₀: every draw is discarded (3 discards, then kept: one exhausted refinement). With s
// moved from (1, 0, 0) to (5/4, 0, 0), a quarter of the radius off the sphere, the first draw is
// kept (no discard).
TEST(PickValid3, ForbiddenConfigurationIsRejectedAndOneJustOutsideAccepted) {
  Polyhedron box = anisocert::geometry::cube_polyhedron();
  for (auto& v : box.vertices) v = {v.x * 8 - 4, v.y * 8 - 4, v.z * 8 - 4};
  const common::Domain3 domain(box);
  const Sym3<double> I{1, 0, 0, 1, 0, 1};
  anisocert::fields::MetricField3 field{"constant", {}, [I](double, double, double) { return I; }};
  anisocert::refiners::star::RefineParameters p;
  p.gamma0 = 1.01, p.delta = 1e-6, p.pick_attempts = 3;
  for (const double sx : {1.0, 1.25}) {
    common::Sites3 sites(domain, field);
    for (const Point3<double>& q : {Point3<double>{0.5, 0.5, 0}, {0.5, 0, 0.5}, {0.5, -0.5, 0}, {sx, 0, 0}}) sites.add(q, I);
    sites.grow_grid();
    anisocert::refiners::star::PickValid3 pick(domain, sites, p);
    const Point3<double> x = pick.pick({0, 0, 0}, 4, I, {0, 1, 2, 3});
    EXPECT_LT(std::abs(x.x) + std::abs(x.y) + std::abs(x.z), 1e-5);
    if (sx == 1.0) {
      EXPECT_EQ(pick.counts().rejected, 3u);
      EXPECT_EQ(pick.counts().exhausted, 1u);
    } else {
      EXPECT_EQ(pick.counts().rejected, 0u);
      EXPECT_EQ(pick.counts().exhausted, 0u);
    }
  }
}
