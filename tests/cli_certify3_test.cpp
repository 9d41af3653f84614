// `anisocert certify` on tetrahedral meshes (issue 39), as a user runs it on a Medit file with its
// .sol: the Kuhn grid of 2 × 2 × 2 unit cubes (48 tetrahedra, valid, Delaunay with 48 cospherical
// ties: mesh_certifier3_test.cpp derives the figures), the same with one tetrahedron reversed, the
// JSON report, and what is refused with exit 2 (a bound not yet written for tetrahedra, a 2D field,
// a tetrahedron naming a vertex that does not exist), nothing written.
#include "cli_run.hpp"
#include "predicates/orientation3.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <vector>

namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("cli_certify3_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The n³ Kuhn grid as Medit text, positively oriented; `flip`: the index of a tetrahedron written
// reversed (−1: none).
std::string kuhn_medit(int n, int flip = -1) {
  std::vector<std::array<int, 3>> v;
  std::vector<std::array<int, 4>> tets;
  const auto vertex = [&](std::array<int, 3> p) {
    const auto at = std::find(v.begin(), v.end(), p);
    if (at != v.end()) return static_cast<int>(at - v.begin());
    v.push_back(p);
    return static_cast<int>(v.size() - 1);
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::array<int, 3> axes{0, 1, 2};
        do {
          std::array<int, 3> p{i, j, k};
          std::array<int, 4> t{};
          t[0] = vertex(p);
          for (std::size_t s = 0; s < 3; ++s) ++p[static_cast<std::size_t>(axes[s])], t[s + 1] = vertex(p);
          const auto P = [&](int q) {
            const auto& c = v[static_cast<std::size_t>(q)];
            return anisocert::predicates::Point3<double>{double(c[0]), double(c[1]), double(c[2])};
          };
          if (anisocert::predicates::orientation3(P(t[0]), P(t[1]), P(t[2]), P(t[3])) == anisocert::Sign::negative) std::swap(t[2], t[3]);
          tets.push_back(t);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  std::string s = "MeshVersionFormatted 2\nDimension 3\nVertices\n" + std::to_string(v.size()) + "\n";
  for (const auto& p : v) s += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + " 0\n";
  s += "Tetrahedra\n" + std::to_string(tets.size()) + "\n";
  for (std::size_t t = 0; t < tets.size(); ++t) {
    auto q = tets[t];
    if (static_cast<int>(t) == flip) std::swap(q[0], q[1]);
    s += std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " + std::to_string(q[3] + 1) + " 1\n";
  }
  return s + "End\n";
}

std::string identity_sol(std::size_t n) {
  std::string s = "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n" + std::to_string(n) + "\n1 3\n";
  for (std::size_t i = 0; i < n; ++i) s += "1 0 1 0 0 1\n";
  return s + "End\n";
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST(CliCertify3, TheKuhnGridIsCertifiedWithItsTies) {
  const fs::path d = fresh("kuhn");
  write(d / "grid.mesh", kuhn_medit(2));
  write(d / "grid.sol", identity_sol(27));  // MMG's convention: BASE.sol beside BASE.mesh
  const Outcome r = run("certify " + (d / "grid.mesh").string() + " --json " + (d / "r.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("27 vertices, 48 tetrahedra"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("positive orientation (Medit's)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("locally uniform (every tetrahedron at v has an empty M_v-circumsphere): holds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("48 cospherical ties"), std::string::npos) << r.out;
  // What validity does not cover yet is said where the verdict is.
  EXPECT_NE(r.out.find("not checked: that it does not cross itself"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("certified"), std::string::npos);
  std::ifstream in(d / "r.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["dimension"], 3);
  EXPECT_EQ(j["tetrahedra"], 48);
  EXPECT_EQ(j["locally_uniform"]["tie_count"], 48);
  EXPECT_EQ(j["valid"]["boundary_faces"], 48);  // 6 sides of 2 × 2 squares, 2 triangles each
  EXPECT_EQ(j["lengths"]["edges"], 98);  // 54 along the axes, 36 face diagonals, 8 cube diagonals
  EXPECT_EQ(j["lengths"]["unit_edges"], 90);  // the cube diagonals (√3) are longer than √2
}

TEST(CliCertify3, AReversedTetrahedronIsNamed) {
  const fs::path d = fresh("flip");
  write(d / "grid.mesh", kuhn_medit(2, 17));
  const Outcome r = run("certify " + (d / "grid.mesh").string());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("tetrahedron 17 is negatively oriented, 47 others positively"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not certified"), std::string::npos);
}

TEST(CliCertify3, WhatIsNotYetWrittenForTetrahedraIsRefused) {
  const fs::path d = fresh("refused");
  write(d / "grid.mesh", kuhn_medit(1));
  write(d / "grid.sol", identity_sol(8));
  const std::string mesh = (d / "grid.mesh").string(), json = (d / "r.json").string();
  for (const std::string& extra : {std::string(" --rho0 2"), std::string(" --svg ") + (d / "r.svg").string(),
                                   std::string(" --field constant")}) {
    const Outcome r = run("certify " + mesh + extra + " --json " + json);
    EXPECT_EQ(r.exit_code, 2) << extra << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("tetrahedral mesh"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(json));
  }
  write(d / "bad.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 5 0\nEnd\n");
  const Outcome bad = run("certify " + (d / "bad.mesh").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.mesh:11: in Tetrahedra: a tetrahedron's vertex 5 is not a vertex (1..4)"), std::string::npos) << bad.err;
  const Outcome dual = run("dual " + mesh);
  EXPECT_EQ(dual.exit_code, 2);
  EXPECT_NE(dual.err.find("is a tetrahedral mesh: `dual` asks"), std::string::npos) << dual.err;
}
