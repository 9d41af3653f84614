// The exact validity check of tetrahedral meshes (oracle/certify/tetrahedralization_check.hpp),
// on meshes built by hand whose answer is known: the unit cube's six Kuhn tetrahedra (each a path
// 000 → e_i → e_i + e_j → 111 along the axes, so all six share the diagonal), with each failure
// the check names made on purpose.

#include "oracle/certify/tetrahedralization_check.hpp"
#include "predicates/orientation3.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

using anisocert::Rational;
using anisocert::Sign;
using namespace anisocert::oracle;
using Mesh3 = anisocert::geometry::Mesh3<Rational>;

namespace {

// The Kuhn tetrahedra of the cube `origin` + [0, 1]³, positively oriented; vertices found or added.
void add_cube(Mesh3& m, std::array<int, 3> origin) {
  const auto vertex = [&](std::array<int, 3> p) {
    const anisocert::predicates::Point3<Rational> q{origin[0] + p[0], origin[1] + p[1], origin[2] + p[2]};
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      if (m.vertices[i].x == q.x && m.vertices[i].y == q.y && m.vertices[i].z == q.z) return static_cast<int>(i);
    m.vertices.push_back(q);
    return static_cast<int>(m.vertices.size() - 1);
  };
  std::array<int, 3> axes{0, 1, 2};
  do {
    std::array<int, 3> p{0, 0, 0};
    std::array<int, 4> t;
    t[0] = vertex(p);
    for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(axes[static_cast<std::size_t>(k)])] = 1, t[static_cast<std::size_t>(k + 1)] = vertex(p);
    const auto& v = m.vertices;
    if (anisocert::predicates::orientation3(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) == Sign::negative) std::swap(t[2], t[3]);
    m.tetrahedra.push_back(t);
  } while (std::next_permutation(axes.begin(), axes.end()));
}

TetrahedralizationCheck check(const Mesh3& m) { return check_tetrahedralization(EnclosedMesh3(m)); }

bool names(const TetrahedralizationCheck& c, const std::string& text) {
  return std::any_of(c.failures.begin(), c.failures.end(), [&](const std::string& f) { return f.find(text) != std::string::npos; });
}

std::string all(const TetrahedralizationCheck& c) {
  std::string s;
  for (const auto& f : c.failures) s += f + "\n";
  return s;
}

}  // namespace

// Six tetrahedra, 24 faces: the cube's 6 squares in 2 triangles each on the boundary, and 6
// interior faces each in two tetrahedra.
TEST(TetrahedralizationCheck, TheKuhnCubeIsValid) {
  Mesh3 m;
  add_cube(m, {0, 0, 0});
  const auto c = check(m);
  EXPECT_TRUE(c.valid) << all(c);
  EXPECT_EQ(c.orientation, "positive");
  EXPECT_EQ(c.boundary_faces, 12u);
  EXPECT_EQ(c.interior_faces, 6u);
  // Every tetrahedron reversed: the other convention, said, and still valid.
  for (auto& t : m.tetrahedra) std::swap(t[0], t[1]);
  const auto r = check(m);
  EXPECT_TRUE(r.valid) << all(r);
  EXPECT_EQ(r.orientation, "negative");
}

TEST(TetrahedralizationCheck, AMixOfOrientationsNamesTheRarerOnes) {
  Mesh3 m;
  add_cube(m, {0, 0, 0});
  std::swap(m.tetrahedra[4][0], m.tetrahedra[4][1]);
  const auto c = check(m);
  EXPECT_FALSE(c.valid);
  EXPECT_TRUE(names(c, "tetrahedron 4 is negatively oriented, 5 others positively")) << all(c);
  EXPECT_EQ(c.bad_tetrahedra, std::vector<int>{4});
}

TEST(TetrahedralizationCheck, FlatAndRepeatedVerticesAreNamed) {
  Mesh3 m;
  add_cube(m, {0, 0, 0});
  m.vertices.push_back({Rational(1, 2), Rational(1, 2), 0});  // in the plane z = 0 with 0, e_x, e_y
  const int flat = static_cast<int>(m.vertices.size() - 1);
  m.tetrahedra.push_back({0, 1, 5, flat});  // (0,0,0), (1,0,0), (0,1,0): the first paths add e_y sixth
  const auto c = check(m);
  EXPECT_TRUE(names(c, "tetrahedron 6")) << all(c);
  EXPECT_TRUE(names(c, "is flat")) << all(c);
}

// Two tetrahedra on the same side of their common face abc: (0,0,0), (1,0,0), (0,1,0) with
// (0,0,1) and with (1/10, 1/10, 1/2), both above z = 0.
TEST(TetrahedralizationCheck, TetrahedraOnOneSideOfAFaceOverlap) {
  Mesh3 m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {Rational(1, 10), Rational(1, 10), Rational(1, 2)}};
  m.tetrahedra = {{0, 1, 2, 3}, {0, 1, 2, 4}};
  const auto c = check(m);
  EXPECT_FALSE(c.valid);
  EXPECT_TRUE(names(c, "face (0, 1, 2) is in tetrahedra 0 and 1, which lie on the same side of it")) << all(c);
}

TEST(TetrahedralizationCheck, AFaceInThreeTetrahedraAndAnUnusedVertex) {
  Mesh3 m;
  add_cube(m, {0, 0, 0});
  m.tetrahedra.push_back(m.tetrahedra[2]);
  m.vertices.push_back({5, 5, 5});
  const auto c = check(m);
  EXPECT_FALSE(c.valid);
  EXPECT_TRUE(names(c, "is in 3 tetrahedra (2, ")) << all(c);
  EXPECT_TRUE(names(c, "vertex 8 is a vertex of no tetrahedron")) << all(c);
}

// Cubes [0,1]³ and [1,2]×[1,2]×[0,1] share only the edge x = y = 1, which is then in four
// boundary faces; cubes [0,1]³ and [1,2]³ share only the vertex (1,1,1), around which the
// boundary faces make two cycles (it is vertex 3: the first path adds 000, 100, 110, 111).
TEST(TetrahedralizationCheck, PinchedEdgesAndVerticesAreNamed) {
  Mesh3 edge;
  add_cube(edge, {0, 0, 0});
  add_cube(edge, {1, 1, 0});
  const auto e = check(edge);
  EXPECT_FALSE(e.valid);
  EXPECT_TRUE(names(e, "is in 4 boundary faces (a pinched edge)")) << all(e);
  Mesh3 vertex;
  add_cube(vertex, {0, 0, 0});
  add_cube(vertex, {1, 1, 1});
  const auto v = check(vertex);
  EXPECT_FALSE(v.valid);
  EXPECT_TRUE(names(v, "vertex 3 is pinched: its boundary faces make 2 cycles around it")) << all(v);
  EXPECT_EQ(v.failure_count, 1u) << all(v);
}

// The declared triangles: the 12 boundary faces, some reversed, pass; an interior face declared
// too is an interface between subdomains (counted, as MMG and Gmsh write them); one boundary face
// missing, one declared twice the same way and three corners that are no face are each named.
TEST(TetrahedralizationCheck, DeclaredTrianglesMustBeTheBoundaryFaces) {
  Mesh3 m;
  add_cube(m, {0, 0, 0});
  // Collect the boundary faces: the faces in one tetrahedron.
  std::vector<std::array<int, 3>> faces;
  for (const auto& t : m.tetrahedra)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f;
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[static_cast<std::size_t>(j++)] = t[static_cast<std::size_t>(k)];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  std::array<int, 3> interior{};
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const bool twice = (i + 1 < faces.size() && faces[i + 1] == faces[i]) || (i > 0 && faces[i - 1] == faces[i]);
    if (!twice) m.triangles.push_back(m.triangles.size() % 2 ? std::array<int, 3>{faces[i][0], faces[i][2], faces[i][1]} : faces[i]);
    else interior = faces[i];
  }
  ASSERT_EQ(m.triangles.size(), 12u);
  const auto ok = check(m);
  EXPECT_TRUE(ok.valid) << all(ok);
  // Each face declared again in the other orientation (CGAL's Medit writer lists a surface facet
  // from both sides): valid, 12 counted; a third declaration of one of them is a failure.
  Mesh3 both = m;
  for (const auto& t : m.triangles) both.triangles.push_back({t[1], t[0], t[2]});
  const auto sides = check(both);
  EXPECT_TRUE(sides.valid) << all(sides);
  EXPECT_EQ(sides.declared_both_sides, 12u);
  both.triangles.push_back({m.triangles[0][2], m.triangles[0][0], m.triangles[0][1]});  // a rotation: the first orientation
  EXPECT_EQ(check(both).failure_count, 1u) << all(check(both));
  const auto missing = m.triangles.back();
  m.triangles.pop_back();
  m.triangles.push_back(m.triangles.front());
  m.triangles.push_back(interior);
  // Three corners of the cube that are no face of its tetrahedra.
  std::array<int, 3> none{};
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int d = b + 1; d < 8; ++d)
        if (!std::binary_search(faces.begin(), faces.end(), std::array<int, 3>{a, b, d})) none = {a, b, d};
  ASSERT_NE(none, (std::array<int, 3>{0, 0, 0}));
  m.triangles.push_back(none);
  const auto c = check(m);
  EXPECT_FALSE(c.valid);
  EXPECT_EQ(c.declared_interfaces, 1u) << all(c);
  EXPECT_TRUE(names(c, "is declared again in the same orientation or a third time")) << all(c);
  EXPECT_TRUE(names(c, "(" + std::to_string(none[0]) + ", " + std::to_string(none[1]) + ", " + std::to_string(none[2]) +
                           ") is not a face of the tetrahedra"))
      << all(c);
  std::array<int, 3> sorted = missing;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(names(c, "the boundary face (" + std::to_string(sorted[0]) + ", " + std::to_string(sorted[1]) + ", " +
                           std::to_string(sorted[2]) + ")"))
      << all(c);
  EXPECT_EQ(c.failure_count, 3u) << all(c);
}
