// `anisocert certify` on tetrahedral meshes (issue 39), as a user runs it on a Medit file with its
// .sol: the Kuhn grid of 2 × 2 × 2 unit cubes (48 tetrahedra, valid, Delaunay with 48 cospherical
// ties: mesh_certifier3_test.cpp derives the figures), the same with one tetrahedron reversed, the
// JSON report, a built-in 3D field, and what is refused with exit 2 (a bound not yet written for
// tetrahedra, a background field,
// a tetrahedron naming a vertex that does not exist), nothing written.
#include "cli_run.hpp"
#include "geometry/kuhn_grid.hpp"
#include "io/formats/medit.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) { return fresh_folder("cli_certify3", name); }

// The n³ Kuhn grid (geometry/kuhn_grid.hpp) as Medit text, by the Medit writer; `flip`: the index
// of a tetrahedron written reversed (−1: none).
std::string kuhn_medit(int n, int flip = -1) {
  anisocert::io::MeshFile f;
  f.dimension = 3;
  f.mesh3 = anisocert::geometry::kuhn_grid(n);
  if (flip >= 0) std::swap(f.mesh3.tetrahedra[static_cast<std::size_t>(flip)][0], f.mesh3.tetrahedra[static_cast<std::size_t>(flip)][1]);
  return anisocert::io::medit_mesh_text(f);
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

// LU's sliver measure in the report, on one Kuhn cube in M = I (by hand: its six tetrahedra share
// the cube's sphere, radius √3/2, so each of the six pairs across its inner faces is exactly
// cospherical, γ₀-cospherical at any γ₀ > 1, with Definition 3.9's ratio √3/2 over edge 1).
TEST(CliCertify3, TheSliverMeasureIsReported) {
  const fs::path d = fresh("sliver");
  write(d / "cube.mesh", kuhn_medit(1));
  write(d / "cube.sol", identity_sol(8));
  const Outcome r = run("certify " + (d / "cube.mesh").string() + " --gamma0 1.0001 --json " + (d / "r.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;  // a measure, not a verdict
  EXPECT_NE(r.out.find("LU's sliver measure (quasi-cosphericity of tetrahedra sharing a face, Definitions 3.6 and 3.9): measured (6 pairs of "
                       "tetrahedra sharing a face; least critical distortion γ* ≈ 1"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("6 exactly cospherical in a vertex's metric; 6 γ₀-cospherical for γ₀ = 1.0001, least radius-edge ratio of those ≈ 0.866025"),
            std::string::npos)
      << r.out;
  std::ifstream in(d / "r.json");
  const nlohmann::json q = nlohmann::json::parse(in)["quasi_cosphericity"];
  EXPECT_EQ(q["configurations"], 6);
  EXPECT_EQ(q["cospherical"], 6);
  EXPECT_EQ(q["least_critical_distortion"], 1.0);
  EXPECT_EQ(q["gamma0"], "1.0001");
  EXPECT_EQ(q["quasi_cospherical"], 6);
  EXPECT_EQ(q["at_boundary"], 0);
  EXPECT_NEAR(q["least_radius_edge"].get<double>(), std::sqrt(3.0) / 2, 1e-12);
  EXPECT_EQ(q["least_radius_edge_tetrahedra"].size(), 2u);
  EXPECT_EQ(q["least_critical_tetrahedra"].size(), 2u);
  EXPECT_EQ(q["unmeasured"], 0);
  ASSERT_EQ(q["witnesses"].size(), 6u);
  EXPECT_EQ(q["witnesses"][0]["tetrahedra"].size(), 2u);
  EXPECT_EQ(q["witnesses"][0]["vertex"], 0);
  // Without γ₀: measured only, the exact counts null.
  const Outcome m = run("certify " + (d / "cube.mesh").string() + " --json " + (d / "m.json").string());
  std::ifstream min(d / "m.json");
  const nlohmann::json n = nlohmann::json::parse(min)["quasi_cosphericity"];
  EXPECT_TRUE(n["quasi_cospherical"].is_null());
  EXPECT_TRUE(n["gamma0"].is_null());
  EXPECT_EQ(n["cospherical"], 6);
}

// A built-in 3D field: the UGAWG linear field on the Kuhn grid of 2 × 2 × 2 unit cubes. At z = 0
// and z = 1 the field is 100·I (h_z = 0.1, by hand from the README's formula), so the cube
// edges there are 10 long: none of unit length, and the report names the field as the source.
// A field with no metric at a vertex (ugawg-polar2 inside its cylinder) is refused naming it.
TEST(CliCertify3, ABuiltIn3DFieldGivesTheMetrics) {
  const fs::path d = fresh("field");
  write(d / "grid.mesh", kuhn_medit(2));
  const std::string json = (d / "r.json").string();
  const Outcome r = run("certify " + (d / "grid.mesh").string() + " --field ugawg-linear --json " + json);
  EXPECT_NE(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("metrics from --field ugawg-linear"), std::string::npos) << r.out;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["metric_source"], "--field ugawg-linear");
  EXPECT_EQ(j["lengths"]["unit_edges"], 0);
  const Outcome no = run("certify " + (d / "grid.mesh").string() + " --field ugawg-polar2");
  EXPECT_EQ(no.exit_code, 2);
  EXPECT_NE(no.err.find("--field ugawg-polar2: at vertex 0: field ugawg-polar2 has no metric at r = 0"), std::string::npos) << no.err;
}

// `metric` writes a 3D field at a tetrahedral mesh's vertices into a Medit .sol (its doubles,
// exactly), and certifying against that file gives the report that --field gives; a BAMG .mtr
// holds 2D metrics only and is refused, nothing written.
TEST(CliCertify3, AFieldWrittenToASolCertifiesAsTheFieldItself) {
  const fs::path d = fresh("metric3");
  write(d / "grid.mesh", kuhn_medit(2));
  const std::string mesh = (d / "grid.mesh").string(), sol = (d / "polar.sol").string();
  const Outcome w = run("metric --field ugawg-polar1 --at " + mesh + " -o " + sol);
  ASSERT_EQ(w.exit_code, 0) << w.err;
  const Outcome a = run("certify " + mesh + " --metric " + sol + " --json " + (d / "a.json").string());
  const Outcome b = run("certify " + mesh + " --field ugawg-polar1 --json " + (d / "b.json").string());
  EXPECT_EQ(a.exit_code, b.exit_code);
  auto ja = nlohmann::json::parse(std::ifstream(d / "a.json")), jb = nlohmann::json::parse(std::ifstream(d / "b.json"));
  ja.erase("metric_source"), jb.erase("metric_source");
  EXPECT_EQ(ja, jb);
  const Outcome mtr = run("metric --field ugawg-polar1 --at " + mesh + " -o " + (d / "polar.mtr").string());
  EXPECT_EQ(mtr.exit_code, 2);
  EXPECT_NE(mtr.err.find("polar.mtr: a bamg metric file holds 2D metrics only"), std::string::npos) << mtr.err;
  EXPECT_FALSE(fs::exists(d / "polar.mtr"));
}

// --min-quality on tetrahedra: the Kuhn tetrahedron's mean ratio is 0.432^(1/3) = 0.7560 for M = I
// (mesh_certifier3_test.cpp derives it), so 3/4 holds and 0.76 fails for all 48.
TEST(CliCertify3, MinQualityIsAVerdictOnTetrahedra) {
  const fs::path d = fresh("quality");
  write(d / "grid.mesh", kuhn_medit(2));
  write(d / "grid.sol", identity_sol(27));
  const std::string mesh = (d / "grid.mesh").string(), json = (d / "q.json").string();
  const Outcome ok = run("certify " + mesh + " --checks valid,metric --min-quality 3/4");
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("mean-ratio quality >= 3/4 in each vertex's metric: holds (least ∈ [0.7559"), std::string::npos) << ok.out;
  const Outcome no = run("certify " + mesh + " --checks valid,metric --min-quality 0.76 --json " + json);
  EXPECT_EQ(no.exit_code, 1) << no.out << no.err;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["quality"]["violation_count"], 48);
  EXPECT_EQ(j["quality"]["least_tetrahedron"].is_number(), true);
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
  // --svg: the section at mid-height (z = 1/2 cuts every tetrahedron of the one Kuhn cube) and the
  // histograms, written with the report.
  const Outcome svg = run("certify " + mesh + " --metric " + (d / "grid.sol").string() + " --svg " + (d / "r.svg").string());
  EXPECT_NE(svg.exit_code, 2) << svg.err;
  std::ifstream picture(d / "r.svg");
  const std::string text((std::istreambuf_iterator<char>(picture)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("the tetrahedra cut by the plane z = 0.5"), std::string::npos);
  EXPECT_NE(text.find("smallest dihedral angle of each tetrahedron"), std::string::npos);
  EXPECT_EQ(std::count(text.begin(), text.end(), 'Z'), 6);  // six sections, one closed path each
  // A tetrahedral background (fields/background3.hpp): the mesh as its own background gives each
  // vertex its own metric (P1 is exact at a vertex), so the verdict is the --metric one.
  const Outcome own = run("certify " + mesh + " --metric " + (d / "grid.sol").string() + " --json " + json);
  const Outcome background = run("certify " + mesh + " --field background:" + mesh);
  EXPECT_EQ(background.exit_code, own.exit_code) << background.err;
  EXPECT_NE(background.out.find("metrics from --field background:"), std::string::npos) << background.out;
  fs::remove(json);
  // A triangle mesh is no background for a tetrahedral one.
  write(d / "flat.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n1\n1 2 3 0\nEnd\n");
  write(d / "flat.sol", "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n3\n1 1\n1\n1\n1\nEnd\n");
  const Outcome flat = run("certify " + mesh + " --field background:" + (d / "flat.mesh").string());
  EXPECT_EQ(flat.exit_code, 2);
  EXPECT_NE(flat.err.find("a triangle mesh is no background for a tetrahedral mesh"), std::string::npos) << flat.err;
  write(d / "bad.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 5 0\nEnd\n");
  const Outcome bad = run("certify " + (d / "bad.mesh").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.mesh:11: in Tetrahedra: a tetrahedron's vertex 5 is not a vertex (1..4)"), std::string::npos) << bad.err;
  const Outcome dual = run("dual " + mesh);
  EXPECT_EQ(dual.exit_code, 2);
  EXPECT_NE(dual.err.find("is a tetrahedral mesh: `dual` asks"), std::string::npos) << dual.err;
}
