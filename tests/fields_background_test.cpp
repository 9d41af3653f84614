// The field of a background mesh (fields/background.hpp): P1 interpolation of the vertex metrics'
// components. Expected values come from the definition's closed forms, not from the code under
// test: λ = (1, 0, 0) at a vertex, (1/2, 1/2, 0) at an edge midpoint, and P1 reproduces affine
// functions exactly (so an affine metric field sampled at the vertices comes back at any point);
// continuity across a shared edge is checked by evaluating in each triangle; positive
// definiteness by Sylvester's criterion, exactly. The CLI tests run the program as a user does.
#include "fields/background.hpp"
#include "io/mesh_json.hpp"

#include "cli_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>

using anisocert::Rational;
using anisocert::fields::background_field;
using anisocert::fields::BackgroundMesh;
using anisocert::fields::BackgroundMeshError;
using anisocert::fields::FieldError;
using Mesh = anisocert::geometry::Mesh<Rational>;
using Point = anisocert::predicates::Point2<Rational>;
using Sym = anisocert::predicates::Sym2<Rational>;

namespace {

// An affine metric field, positive definite on [0, 1]²: m11 ∈ [2, 3], m22 ∈ [2, 3], |m12| ≤ 1/4.
template <class T>
anisocert::predicates::Sym2<T> affine(const T& x, const T& y) {
  return {2 + x, (x - y) / 4, 3 - y};
}

// The unit square cut into n × n cells of two counter-clockwise triangles each, (i/n, j/n) at
// index j (n + 1) + i; the interior vertices moved by up to 1/(5n) in each direction (rational
// offsets), which keeps every triangle counter-clockwise. Metrics: the affine field at each vertex.
Mesh square_mesh(int n, std::mt19937& rng, bool jitter) {
  std::uniform_int_distribution<int> offset(-1000, 1000);
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Point p{Rational(i, n), Rational(j, n)};
      if (jitter && i > 0 && i < n && j > 0 && j < n) {
        p.x += Rational(offset(rng), 5000 * n);
        p.y += Rational(offset(rng), 5000 * n);
      }
      m.sites.push_back(p);
      m.metrics.push_back(affine(p.x, p.y));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
      m.triangles.push_back({v00, v10, v11});
      m.triangles.push_back({v00, v11, v01});
    }
  return m;
}

// A positive definite metric with eigenvalues a and b along a rational rotation ((1 − t², 2t) / (1 + t²)).
Sym rotated(const Rational& a, const Rational& b, const Rational& t) {
  const Rational c = (1 - t * t) / (1 + t * t), s = 2 * t / (1 + t * t);
  return {a * c * c + b * s * s, (a - b) * c * s, a * s * s + b * c * c};
}

// Random strongly anisotropic metrics (eigenvalue ratios up to 10⁶) at every site.
void randomize_metrics(Mesh& m, std::mt19937& rng) {
  std::uniform_int_distribution<int> eigen(1, 1000000), turn(-50, 50);
  for (Sym& M : m.metrics) M = rotated(Rational(eigen(rng)), Rational(1, eigen(rng)), Rational(turn(rng), 7));
}

// A random rational in [0, 1] with a denominator up to 10⁶.
Rational random_unit(std::mt19937& rng) {
  const int den = std::uniform_int_distribution<int>(1, 1000000)(rng);
  return Rational(std::uniform_int_distribution<int>(0, den)(rng), den);
}

void expect_equal(const Sym& got, const Sym& expected, const std::string& where) {
  EXPECT_EQ(got.m11, expected.m11) << where;
  EXPECT_EQ(got.m12, expected.m12) << where;
  EXPECT_EQ(got.m22, expected.m22) << where;
}

std::string text(const Point& p) { return "(" + anisocert::to_exact_string(p.x) + ", " + anisocert::to_exact_string(p.y) + ")"; }

std::string construction_error(const Mesh& m) {
  try {
    BackgroundMesh b(m);
  } catch (const BackgroundMeshError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST(BackgroundMesh, VertexGivesItsMetric) {
  std::mt19937 rng(1);
  Mesh m = square_mesh(4, rng, true);
  randomize_metrics(m, rng);
  const BackgroundMesh b(m);
  for (std::size_t i = 0; i < m.sites.size(); ++i) {
    const auto M = b.metric_at(m.sites[i]);
    ASSERT_TRUE(M) << "site " << i;
    expect_equal(*M, m.metrics[i], "site " + std::to_string(i));
  }
}

TEST(BackgroundMesh, EdgeMidpointAveragesItsEndpoints) {
  std::mt19937 rng(2);
  Mesh m = square_mesh(4, rng, true);
  randomize_metrics(m, rng);
  const BackgroundMesh b(m);
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      const Point mid{(m.sites[i].x + m.sites[j].x) / 2, (m.sites[i].y + m.sites[j].y) / 2};
      const Sym &Mi = m.metrics[i], &Mj = m.metrics[j];
      const auto M = b.metric_at(mid);
      ASSERT_TRUE(M);
      expect_equal(*M, {(Mi.m11 + Mj.m11) / 2, (Mi.m12 + Mj.m12) / 2, (Mi.m22 + Mj.m22) / 2},
                   "midpoint of sites " + std::to_string(i) + ", " + std::to_string(j));
    }
}

TEST(BackgroundMesh, ReproducesAnAffineMetricField) {
  std::mt19937 rng(3);
  const BackgroundMesh b(square_mesh(6, rng, true));
  for (int k = 0; k < 2000; ++k) {
    const Point p{random_unit(rng), random_unit(rng)};
    const auto M = b.metric_at(p);
    ASSERT_TRUE(M) << text(p);
    expect_equal(*M, affine(p.x, p.y), text(p));
  }
}

// On an edge shared by two triangles each gives the same value (P1 is continuous), and so does
// metric_at, whichever triangle it finds; at a vertex every triangle around it gives its metric.
TEST(BackgroundMesh, SharedEdgesAndVerticesHaveOneValue) {
  std::mt19937 rng(4);
  Mesh m = square_mesh(3, rng, true);
  randomize_metrics(m, rng);
  const BackgroundMesh b(m);
  std::map<std::pair<int, int>, int> first_side;  // a directed edge, to the triangle that has it
  int shared = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = m.triangles[t][k], j = m.triangles[t][(k + 1) % 3];
      const auto other = first_side.find({j, i});
      if (other == first_side.end()) {
        first_side[{i, j}] = static_cast<int>(t);
        continue;
      }
      ++shared;
      for (int s = 0; s < 20; ++s) {
        const Rational u = random_unit(rng);
        const Point p{m.sites[i].x + u * (m.sites[j].x - m.sites[i].x), m.sites[i].y + u * (m.sites[j].y - m.sites[i].y)};
        const auto here = b.metric_in(static_cast<int>(t), p), there = b.metric_in(other->second, p), any = b.metric_at(p);
        ASSERT_TRUE(here && there && any) << text(p);
        expect_equal(*here, *there, "edge " + std::to_string(i) + "-" + std::to_string(j) + " at " + text(p));
        expect_equal(*any, *here, text(p));
      }
    }
  EXPECT_EQ(shared, 3 * 3 * 3 - 2 * 3);  // 3n² − 2n interior edges: the test saw them all
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int v : m.triangles[t]) {
      const auto M = b.metric_in(static_cast<int>(t), m.sites[v]);
      ASSERT_TRUE(M);
      expect_equal(*M, m.metrics[v], "site " + std::to_string(v) + " in triangle " + std::to_string(t));
    }
}

// metric_in gives nothing outside its triangle (no extrapolation): the centroid of one triangle
// in the other triangle of its cell.
TEST(BackgroundMesh, TriangleGivesNothingOutsideItself) {
  std::mt19937 rng(5);
  const Mesh m = square_mesh(1, rng, false);
  const BackgroundMesh b(m);
  const Point lower{Rational(2, 3), Rational(1, 3)}, upper{Rational(1, 3), Rational(2, 3)};
  EXPECT_TRUE(b.metric_in(0, lower));
  EXPECT_FALSE(b.metric_in(0, upper));
  EXPECT_FALSE(b.metric_in(1, lower));
  EXPECT_TRUE(b.metric_in(1, upper));
}

TEST(BackgroundMesh, ConvexCombinationsStayPositiveDefinite) {
  std::mt19937 rng(6);
  Mesh m = square_mesh(5, rng, true);
  randomize_metrics(m, rng);
  const BackgroundMesh b(m);
  for (int k = 0; k < 2000; ++k) {
    const Point p{random_unit(rng), random_unit(rng)};
    const auto M = b.metric_at(p);
    ASSERT_TRUE(M) << text(p);
    EXPECT_GT(M->m11, 0) << text(p);
    EXPECT_GT(M->m11 * M->m22 - M->m12 * M->m12, 0) << text(p);
  }
}

// The mesh covers exactly [0, 1]²: its boundary is in (closed triangles), anything beyond is not,
// however close; the refiners' field says which point it was asked about.
TEST(BackgroundMesh, PointOutsideHasNoValue) {
  std::mt19937 rng(7);
  const auto b = std::make_shared<const BackgroundMesh>(square_mesh(4, rng, false));
  const Rational nano(1, 1000000000), tiny = nano * nano * nano * nano;  // 10⁻³⁶
  EXPECT_TRUE(b->metric_at(Point{1, Rational(1, 3)}));
  EXPECT_TRUE(b->metric_at(Point{0, 0}));
  EXPECT_FALSE(b->metric_at(Point{1 + tiny, Rational(1, 3)}));
  EXPECT_FALSE(b->metric_at(Point{Rational(1, 2), -tiny}));
  EXPECT_FALSE(b->metric_at(Point{-5, 7}));
  const double beyond = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(b->metric_at(anisocert::predicates::Point2<double>{0.5, beyond}));
  EXPECT_FALSE(b->metric_at(anisocert::predicates::Point2<double>{std::numeric_limits<double>::quiet_NaN(), 0.5}));
  const auto field = background_field(b, "background:bg.json");
  try {
    field.at(0.5, beyond);
    FAIL() << "no error outside the background mesh";
  } catch (const FieldError& e) {
    EXPECT_EQ(std::string(e.what()),
              "the metric field background:bg.json has no value at (0.5, 1.0000000000000002): no background triangle holds it");
  }
}

TEST(BackgroundMesh, RejectsMeshesThatDefineNoField) {
  std::mt19937 rng(8);
  // Sites 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1) here; messages count from 1, as Medit and FreeFem files do.
  const Mesh good = square_mesh(1, rng, false);
  Mesh clockwise = good;
  std::swap(clockwise.triangles[1][1], clockwise.triangles[1][2]);
  EXPECT_EQ(construction_error(clockwise), "background triangle 2 (sites 1, 3, 4; counted from 1 in the file's order) is clockwise");
  Mesh flat = good;
  flat.sites.push_back({2, 2});
  flat.metrics.push_back({1, 0, 1});
  flat.triangles.push_back({0, 3, 4});
  EXPECT_EQ(construction_error(flat), "background triangle 3 (sites 1, 4, 5; counted from 1 in the file's order) is flat: (0, 0), (1, 1) and (2, 2) are collinear");
  Mesh missing = good;
  missing.metrics.pop_back();
  EXPECT_EQ(construction_error(missing), "the background mesh has 4 sites but 3 metrics");
  Mesh indefinite = good;
  indefinite.metrics[2] = {1, 2, 1};
  EXPECT_NE(construction_error(indefinite).find("background site 3 (counted from 1): metric [1, 2, 1] is not positive definite"), std::string::npos)
      << construction_error(indefinite);
  Mesh bare = good;
  bare.triangles.clear();
  EXPECT_EQ(construction_error(bare), "the background mesh has no triangles");
  // A site beyond the doubles in one coordinate, just past the largest double (its interval's
  // upper end infinite, the lower one finite: campaign mutant 187 let such an x through to the grid).
  for (const bool in_x : {true, false}) {
    Mesh far = good;
    const Rational beyond = anisocert::rational_from_double(std::numeric_limits<double>::max()) + 1;  // below 2¹⁰²⁴
    (in_x ? far.sites[3].x : far.sites[3].y) = beyond;
    EXPECT_NE(construction_error(far).find("background site 4 (counted from 1)"), std::string::npos) << construction_error(far);
    EXPECT_NE(construction_error(far).find("lies beyond the range of doubles"), std::string::npos) << construction_error(far);
  }
  // A triangle naming no site (the readers refuse it first; the class on its own too: campaign
  // mutant 177 let it through to an out-of-range read).
  for (const int k : {4, -1}) {
    Mesh beyond = good;
    beyond.triangles[0][1] = k;
    EXPECT_NE(construction_error(beyond).find("names a site beyond the 4 there are"), std::string::npos) << k;
  }
  EXPECT_EQ(construction_error(good), "(accepted)");
}

// The refiners' field is within 2⁻⁴¹ relative of the exact value (background.hpp: m11 and m22 of
// themselves, m12 of √(m11 m22)).
void expect_within_bound(const anisocert::predicates::Sym2<double>& got, const anisocert::predicates::Sym2<double>& exact,
                         const std::string& where) {
  const double bound = 0x1p-41 * (1 + 0x1p-10);  // and the rounding of `exact` and of the scale
  const double scale = std::sqrt(exact.m11 * exact.m22);
  EXPECT_LE(std::abs(got.m11 - exact.m11), bound * exact.m11) << where;
  EXPECT_LE(std::abs(got.m22 - exact.m22), bound * exact.m22) << where;
  EXPECT_LE(std::abs(got.m12 - exact.m12), bound * scale) << where;
}

// Against the affine closed form (independent of the code), evaluated in doubles: its own error
// is a few ulps, far inside the bound.
TEST(BackgroundMesh, DoubleFieldFollowsTheAffineClosedForm) {
  std::mt19937 rng(9);
  const auto field = background_field(std::make_shared<const BackgroundMesh>(square_mesh(8, rng, true)), "bg");
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const double x = unit(rng), y = unit(rng);
    expect_within_bound(field.at(x, y), affine(x, y), std::to_string(x) + ", " + std::to_string(y));
  }
}

// Against the exact value rounded, where the intervals cannot always be tight: random metrics with
// 10⁶ : 1 anisotropy, and the cell at the origin, whose m11 falls from 10¹² at (0, 0) to 1 at its
// other corners (sites 1, 9 and 10, all doubles): on the cell's far edges x = 1/8 and y = 1/8, and
// an ulp inside, the affine form cancels 12 digits, so the exact value must be used.
TEST(BackgroundMesh, DoubleFieldIsTheExactValueRounded) {
  std::mt19937 rng(10);
  Mesh m = square_mesh(8, rng, false);
  randomize_metrics(m, rng);
  m.metrics[0] = {Rational(1000000000000), 0, 1};
  m.metrics[1] = m.metrics[9] = m.metrics[10] = {1, 0, 1};
  const BackgroundMesh b(m);
  std::uniform_real_distribution<double> unit(0, 1), side(0, 0.125);
  for (int k = 0; k < 4000; ++k) {
    double x = unit(rng), y = unit(rng);
    if (k % 2) {
      const double edge = k % 4 == 1 ? 0.125 : std::nextafter(0.125, 0.0);
      x = edge, y = side(rng);
      if (k % 8 >= 4) std::swap(x, y);
    }
    const auto got = b.metric_at(anisocert::predicates::Point2<double>{x, y});
    const auto exact = b.metric_at(Point{Rational(x), Rational(y)});
    ASSERT_TRUE(got && exact);
    expect_within_bound(*got, {exact->m11.convert_to<double>(), exact->m12.convert_to<double>(), exact->m22.convert_to<double>()},
                        std::to_string(x) + ", " + std::to_string(y));
  }
}

// At a vertex the double field is the vertex's own metric rounded to nearest, bit for bit (found by
// refine --from on a grid in 16 I: the intervals' midpoint gave 16 + 2⁻⁴⁸ there, and an edge of
// exactly √2 in the metric counted as too long); random metrics, and the constant 16 I.
TEST(BackgroundMesh, DoubleFieldAtAVertexIsItsMetricRounded) {
  std::mt19937 rng(12);
  for (const bool constant : {true, false}) {
    Mesh m = square_mesh(8, rng, false);  // vertices i/8: doubles
    if (constant)
      for (Sym& M : m.metrics) M = {16, 0, 16};
    else
      randomize_metrics(m, rng);
    const BackgroundMesh b(m);
    for (std::size_t k = 0; k < m.sites.size(); ++k) {
      const auto got = b.metric_at(anisocert::predicates::Point2<double>{m.sites[k].x.convert_to<double>(), m.sites[k].y.convert_to<double>()});
      ASSERT_TRUE(got) << k;
      const Sym& M = m.metrics[k];
      EXPECT_EQ(got->m11, M.m11.convert_to<double>()) << k;
      EXPECT_EQ(got->m12, M.m12.convert_to<double>()) << k;
      EXPECT_EQ(got->m22, M.m22.convert_to<double>()) << k;
    }
  }
}

// Where triangles overlap (not a conforming mesh), the value is the lowest-indexed triangle's,
// whatever the order the grid finds them in: two triangles on the base (0, 0)–(4, 0) with apexes
// (0, 4) and (4, 4), metrics differing at the apexes, meet over (2, 1).
TEST(BackgroundMesh, OverlapsTakeTheLowestIndexedTriangle) {
  Mesh m;
  m.sites = {{0, 0}, {4, 0}, {0, 4}, {4, 4}};
  m.metrics = {{1, 0, 1}, {1, 0, 1}, {9, 0, 1}, {1, 0, 9}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  const Point p{2, 1};
  const BackgroundMesh first(m);
  ASSERT_TRUE(first.metric_in(0, p) && first.metric_in(1, p));
  ASSERT_NE(first.metric_in(0, p)->m11, first.metric_in(1, p)->m11);
  expect_equal(*first.metric_at(p), *first.metric_in(0, p), "triangle 0 first");
  std::swap(m.triangles[0], m.triangles[1]);
  const BackgroundMesh second(m);
  expect_equal(*second.metric_at(p), *second.metric_in(0, p), "triangle 0 second");
  expect_equal(*second.metric_at(p), *first.metric_in(1, p), "the other triangle");
}

// 10⁵ triangles: every random point is found, with the affine field's exact value (the grid must
// not lose a triangle, whatever the rounding of its cells).
TEST(BackgroundMesh, LocatesAmongManyTriangles) {
  std::mt19937 rng(11);
  const BackgroundMesh b(square_mesh(224, rng, true));
  ASSERT_GE(b.triangle_count(), 100000u);
  for (int k = 0; k < 5000; ++k) {
    const Point p{random_unit(rng), random_unit(rng)};
    const auto M = b.metric_at(p);
    ASSERT_TRUE(M) << text(p);
    expect_equal(*M, affine(p.x, p.y), text(p));
  }
}

namespace {

// A file in the test's temporary directory.
std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = ::testing::TempDir() + "anisocert_bg_" + std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << content;
  return path;
}

// The rectangle [0, 1] × [0, h] as two triangles, edge lengths from 1/100 to 1/10 in the metrics
// (before the refiner sampled the field only in Ω, it asked about points beyond x = 1 or y = 0 on
// this mesh for every seed tried).
Mesh rectangle(const Rational& h) {
  Mesh m;
  m.sites = {{0, 0}, {1, 0}, {1, h}, {0, h}};
  m.metrics = {{2500, 0, 2500}, {100, 0, 10000}, {2500, 0, 2500}, {10000, 0, 100}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(BackgroundCli, RefinesForABackgroundMesh) {
  const std::string bg = temp_file("square.json", anisocert::io::mesh_json(rectangle(1)));
  const std::string out = ::testing::TempDir() + "anisocert_bg_" + std::to_string(getpid()) + "_out.json";
  std::filesystem::remove(out);
  const Outcome r = run("refine --field background:" + bg + " --max-vertices 2000 --quiet -o " + out);
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.exit_code << ": " << r.err;
  EXPECT_NE(r.out.find("field background:" + bg), std::string::npos) << r.out;
  ASSERT_TRUE(std::filesystem::exists(out));
  const Mesh refined = anisocert::io::read_mesh_json_file(out);
  EXPECT_GT(refined.triangles.size(), 1000u);  // edges of 1/100 to 1/10 on the unit square: thousands
}

TEST(BackgroundCli, UncoveredPointIsBadInput) {
  const std::string bg = temp_file("half.json", anisocert::io::mesh_json(rectangle(Rational(1, 2))));
  const Outcome r = run("refine --field background:" + bg + " --max-vertices 2000 --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("has no value at ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no background triangle holds it"), std::string::npos) << r.err;
}

// Medit .mesh has no metric of its own: without :METRIC and without BASE.sol beside it that is bad
// input; BASE.sol beside it is its metric (MMG's convention), and :METRIC names one explicitly.
TEST(BackgroundCli, MeshWithoutMetricNeedsAMetricFile) {
  const char* square = "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                       "Triangles\n2\n1 2 3 0\n1 3 4 0\nEnd\n";
  const std::string bare_mesh = temp_file("bare.mesh", square);
  const std::string mesh = temp_file("square.mesh", square);
  const std::string sol = temp_file("square.sol",
                                    "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 3\n25 0 25\n25 0 25\n25 0 25\n"
                                    "25 0 25\nEnd\n");
  const Outcome bare = run("refine --field background:" + bare_mesh + " --quiet");
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("background mesh has no metric (give MESH:METRIC)"), std::string::npos) << bare.err;
  for (const std::string& field : {mesh, mesh + ":" + sol}) {
    const Outcome with = run("refine --field background:" + field + " --max-vertices 2000 --quiet");
    EXPECT_TRUE(with.exit_code == 0 || with.exit_code == 1) << field << ": " << with.exit_code << ": " << with.err;
  }
}

TEST(BackgroundCli, BackgroundFieldTakesNoParameters) {
  const std::string bg = temp_file("params.json", anisocert::io::mesh_json(rectangle(1)));
  const Outcome r = run("refine --field background:" + bg + " --param h=0.1 --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--param: a background field has no parameters"), std::string::npos) << r.err;
}
