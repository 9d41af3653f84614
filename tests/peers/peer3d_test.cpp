// 3D peers (issue 39): Gmsh and TetGen mesh the unit box with tetrahedra (Delaunay, then an
// optimiser that does not keep the Delaunay property), CGAL Mesh_3 the unit ball, and `anisocert certify` decides each
// mesh's validity and local uniformity for M = I, i.e. which tetrahedra have a vertex strictly
// inside their circumsphere. The count is checked against a brute force written here from the
// definition, sharing no code with the certifier or the readers: the files parsed by hand (MSH
// 2.2 ASCII; TetGen's .node/.ele; CGAL's Medit), each circumcentre solved from three linear equations in
// rationals, every vertex's squared distance compared with the radius².
#include "numbers/rational.hpp"
#include "tests/cli_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <map>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using anisocert::Rational;
using Point = std::array<Rational, 3>;

struct Tets {
  std::vector<Point> vertices;
  std::vector<std::array<std::size_t, 4>> tetrahedra;
};

// MSH 2.2 ASCII: $Nodes (tag x y z), $Elements (tag type ntags tags... nodes); type 4 only.
Tets parse_msh22(const std::string& path) {
  std::ifstream in(path);
  Tets t;
  std::string word;
  std::map<long, std::size_t> index;
  while (in >> word) {
    if (word == "$Nodes") {
      std::size_t n = 0;
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        long tag = 0;
        std::string x, y, z;
        in >> tag >> x >> y >> z;
        index[tag] = i;
        t.vertices.push_back({anisocert::parse_rational(x), anisocert::parse_rational(y), anisocert::parse_rational(z)});
      }
    } else if (word == "$Elements") {
      std::size_t n = 0;
      in >> n;
      std::string line;
      std::getline(in, line);
      for (std::size_t i = 0; i < n && std::getline(in, line);) {
        std::istringstream s(line);
        long tag = 0, type = 0, ntags = 0, v = 0;
        if (!(s >> tag >> type >> ntags)) continue;
        ++i;
        for (long k = 0; k < ntags; ++k) s >> v;
        if (type != 4) continue;
        std::array<std::size_t, 4> tet{};
        for (auto& x : tet) s >> v, x = index.at(v);
        t.tetrahedra.push_back(tet);
      }
    }
  }
  return t;
}

// TetGen's .node ("n 3 attributes markers", then "i x y z ...") and .ele ("n 4 attribute", then
// "i a b c d ..."), numbered from 1 as tetgen writes them by default.
Tets parse_tetgen(const std::string& base) {
  Tets t;
  std::ifstream node(base + ".node"), ele(base + ".ele");
  std::size_t n = 0, dim = 0, attributes = 0, markers = 0;
  node >> n >> dim >> attributes >> markers;
  for (std::size_t i = 0; i < n; ++i) {
    std::string k, x, y, z, skip;
    node >> k >> x >> y >> z;
    for (std::size_t a = 0; a < attributes + markers; ++a) node >> skip;
    t.vertices.push_back({anisocert::parse_rational(x), anisocert::parse_rational(y), anisocert::parse_rational(z)});
  }
  std::size_t m = 0, nodes = 0, region = 0;
  ele >> m >> nodes >> region;
  for (std::size_t i = 0; i < m; ++i) {
    std::size_t k = 0, skip = 0;
    std::array<std::size_t, 4> tet{};
    ele >> k >> tet[0] >> tet[1] >> tet[2] >> tet[3];
    for (auto& v : tet) --v;
    for (std::size_t a = 0; a < region; ++a) ele >> skip;
    t.tetrahedra.push_back(tet);
  }
  return t;
}

// Medit ASCII as CGAL writes it: "Vertices n" then "x y z ref", "Tetrahedra n" then "a b c d ref",
// numbered from 1.
Tets parse_medit(const std::string& path) {
  std::ifstream in(path);
  Tets t;
  std::string word;
  while (in >> word) {
    std::size_t n = 0;
    if (word == "Vertices") {
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        std::string x, y, z, ref;
        in >> x >> y >> z >> ref;
        t.vertices.push_back({anisocert::parse_rational(x), anisocert::parse_rational(y), anisocert::parse_rational(z)});
      }
    } else if (word == "Tetrahedra") {
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        std::array<std::size_t, 4> tet{};
        std::size_t ref = 0;
        in >> tet[0] >> tet[1] >> tet[2] >> tet[3] >> ref;
        for (auto& v : tet) --v;
        t.tetrahedra.push_back(tet);
      }
    }
  }
  return t;
}

Rational distance2(const Point& p, const Point& q) {
  Rational d = 0;
  for (std::size_t i = 0; i < 3; ++i) d += (p[i] - q[i]) * (p[i] - q[i]);
  return d;
}

// The circumcentre c: 2 (p_k − p_0)·c = |p_k|² − |p_0|², k = 1, 2, 3, by Gauss–Jordan elimination.
Point circumcentre(const std::array<Point, 4>& p) {
  std::array<std::array<Rational, 4>, 3> a;
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t i = 0; i < 3; ++i) a[k][i] = 2 * (p[k + 1][i] - p[0][i]);
    a[k][3] = distance2(p[k + 1], Point{0, 0, 0}) - distance2(p[0], Point{0, 0, 0});
  }
  for (std::size_t c = 0; c < 3; ++c) {
    std::size_t pivot = c;
    while (a[pivot][c] == 0) ++pivot;  // the tetrahedron is not flat: a pivot exists
    std::swap(a[c], a[pivot]);
    for (std::size_t r = 0; r < 3; ++r)
      if (r != c && a[r][c] != 0) {
        const Rational f = a[r][c] / a[c][c];
        for (std::size_t j = c; j < 4; ++j) a[r][j] -= f * a[c][j];
      }
  }
  return {a[0][3] / a[0][0], a[1][3] / a[1][1], a[2][3] / a[2][2]};
}

// Certifies `mesh` (read by anisocert) for M = I and compares with the brute force on `t`; returns
// the report.
nlohmann::json expect_brute_force_count(const std::string& peer, const fs::path& dir, const std::string& mesh, const Tets& t) {
  EXPECT_GT(t.tetrahedra.size(), 100u);
  // M = I at every vertex: a Medit .sol of sizes h = 1.
  {
    std::ofstream sol(dir / "box.sol");
    sol << "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n" << t.vertices.size() << "\n1 1\n";
    for (std::size_t i = 0; i < t.vertices.size(); ++i) sol << "1\n";
    sol << "End\n";
  }
  const std::string json = (dir / "c.json").string();
  const Outcome r = run_command(std::string(ANISOCERT_BIN) + " certify " + mesh + " --metric " + (dir / "box.sol").string() +
                                " --json " + json);
  EXPECT_NE(r.exit_code, 2) << r.out << r.err;
  if (r.exit_code == 2) return {};
  std::size_t violated = 0, tied_only = 0, tied = 0;
  for (const auto& tet : t.tetrahedra) {
    const std::array<Point, 4> p{t.vertices[tet[0]], t.vertices[tet[1]], t.vertices[tet[2]], t.vertices[tet[3]]};
    const Point c = circumcentre(p);
    const Rational r2 = distance2(c, p[0]);
    bool inside = false, on = false;
    for (std::size_t v = 0; v < t.vertices.size(); ++v) {
      if (v == tet[0] || v == tet[1] || v == tet[2] || v == tet[3]) continue;
      const Rational d = distance2(c, t.vertices[v]);
      inside = inside || d < r2, on = on || d == r2;
    }
    violated += inside, tied_only += on && !inside, tied += on;
  }
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_TRUE(j["valid"]["holds"].get<bool>()) << r.out;
  EXPECT_EQ(j["tetrahedra"].get<std::size_t>(), t.tetrahedra.size());
  // One witness per tetrahedron: the violations are the tetrahedra with a vertex inside, exactly;
  // a tie is recorded for a tetrahedron whose first finding is one, so the tie count lies between
  // the tetrahedra with only ties and those with any.
  EXPECT_EQ(j["locally_uniform"]["violation_count"].get<std::size_t>(), violated) << r.out;
  EXPECT_GE(j["locally_uniform"]["tie_count"].get<std::size_t>(), tied_only) << r.out;
  EXPECT_LE(j["locally_uniform"]["tie_count"].get<std::size_t>(), tied) << r.out;
  EXPECT_EQ(r.exit_code, violated == 0 ? 0 : 1) << r.out;
  std::printf("%s: %zu tetrahedra, %zu with a vertex strictly inside their circumsphere, %zu tied\n", peer.c_str(),
              t.tetrahedra.size(), violated, tied);
  return j;
}

fs::path fresh_dir(const std::string& peer) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("anisocert_peer3d_" + peer + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(Gmsh3D, LocallyUniformVerdictIsTheBruteForceCount) {
  const fs::path dir = fresh_dir("gmsh");
  std::ofstream(dir / "box.geo") << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\nMesh.CharacteristicLengthMax = 0.3;\n";
  const std::string mesh = (dir / "box.msh").string();
  ASSERT_EQ(run_command("gmsh -3 " + (dir / "box.geo").string() + " -format msh22 -o " + mesh + " > /dev/null 2>&1").exit_code, 0);
  expect_brute_force_count("gmsh", dir, mesh, parse_msh22(mesh));
  fs::remove_all(dir);
}

// The unit cube as a TetGen PLC (six square facets, markers 1 to 6), meshed with quality and a
// volume bound: `tetgen -pq1.414a0.01 box.poly` writes box.1.node/.ele/.face.
TEST(TetGen3D, LocallyUniformVerdictIsTheBruteForceCount) {
  const fs::path dir = fresh_dir("tetgen");
  std::ofstream poly(dir / "box.poly");
  poly << "8 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n6 1\n";
  for (const char* facet : {"1 2 3 4", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"}) poly << "1 0 1\n4 " << facet << "\n";
  poly << "0\n0\n";
  poly.close();
  ASSERT_EQ(run_command("cd " + dir.string() + " && tetgen -pq1.414a0.01 box.poly > /dev/null 2>&1").exit_code, 0);
  expect_brute_force_count("tetgen", dir, (dir / "box.1.ele").string(), parse_tetgen((dir / "box.1").string()));
  fs::remove_all(dir);
}

// CGAL Mesh_3 (tests/cgal/mesh3_peer.cpp) on the unit ball: Delaunay refinement without perturbation
// or exudation, so no vertex lies inside a circumsphere; its Medit file lists every boundary facet
// from both sides, which the certifier counts instead of failing.
TEST(CgalMesh3, LocallyUniformVerdictIsTheBruteForceCount) {
  const fs::path dir = fresh_dir("cgal");
  const std::string mesh = (dir / "ball.mesh").string();
  ASSERT_EQ(run_command(std::string(CGAL_MESH3_PEER) + " " + mesh + " 0.25 > /dev/null").exit_code, 0);
  const nlohmann::json j = expect_brute_force_count("cgal", dir, mesh, parse_medit(mesh));
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["valid"]["declared_both_sides"], j["valid"]["boundary_faces"]);
  fs::remove_all(dir);
}

// The kept meshes of the three peers (fixtures/README.md), certified without the peers.
TEST(Peer3DFixtures, EachIsCertifiedAsTheBruteForceSays) {
  const std::string fixtures = std::string(ANISOCERT_SOURCE_DIR) + "/tests/peers/fixtures/";
  const fs::path dir = fresh_dir("fixtures");
  expect_brute_force_count("gmsh fixture", dir, fixtures + "gmsh-box-h0.3.msh", parse_msh22(fixtures + "gmsh-box-h0.3.msh"));
  expect_brute_force_count("tetgen fixture", dir, fixtures + "tetgen-box-q1.414a0.01.ele", parse_tetgen(fixtures + "tetgen-box-q1.414a0.01"));
  const nlohmann::json cgal = expect_brute_force_count("cgal fixture", dir, fixtures + "cgal-ball-h0.25.mesh", parse_medit(fixtures + "cgal-ball-h0.25.mesh"));
  ASSERT_FALSE(cgal.empty());
  EXPECT_EQ(cgal["locally_uniform"]["violation_count"], 0);
  fs::remove_all(dir);
}

}  // namespace
