// `anisocert refine` on a 3D domain (issue 40), as a user runs it: the built-in cube under a
// constant field, its files read back by `anisocert certify` (the certificate is of the numbers
// written), and what is refused with exit 2, one line, nothing written: an open surface, an
// inward one, a coordinate that is not a double, a refiner that meshes polygons only, a field
// with no metric at a vertex of the domain.
#include "cli_run.hpp"

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) { return fresh_folder("cli_refine3", name); }

// The unit cube as OFF text, its facets outward, or (inward) every facet reversed, or (open) the
// last facet left out; `x1`: the text of the coordinate 1 of vertex 1.
std::string cube_off(bool inward = false, bool open = false, const std::string& x1 = "1") {
  std::string s = "OFF\n8 " + std::string(open ? "11" : "12") + " 0\n";
  for (int k = 0; k < 8; ++k)
    s += (k == 1 ? x1 : std::to_string(k & 1)) + " " + std::to_string((k >> 1) & 1) + " " + std::to_string((k >> 2) & 1) + "\n";
  const int f[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (int i = 0; i < (open ? 11 : 12); ++i)
    s += "3 " + std::to_string(f[i][0]) + " " + std::to_string(inward ? f[i][2] : f[i][1]) + " " + std::to_string(inward ? f[i][1] : f[i][2]) + "\n";
  return s;
}

}  // namespace

TEST(CliRefine3, TheCubeIsRefinedCertifiedAndReadBack) {
  const fs::path d = fresh("cube");
  const std::string mesh = (d / "cube.mesh").string(), json = (d / "cube.json").string();
  const Outcome r = run("refine --domain cube --field constant --param m11=16 --param m22=16 --param m33=16 --quiet -o " + mesh +
                        " --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("star refiner (3D)"), std::string::npos);
  EXPECT_NE(r.out.find("stopped: all stars consistent"), std::string::npos);
  EXPECT_NE(r.out.find("\ncertified"), std::string::npos) << r.out;
  // The cube's twelve ridges are right angles (docs/refiners.md): LU Lemma 4.1's hypothesis fails.
  EXPECT_NE(r.out.find("(dihedral angles > 90° in the metric, for rule 1 to end): not at 12 of 12 ridges"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("edge lengths"), std::string::npos) << r.out;  // the metric checks, measured
  EXPECT_TRUE(fs::exists(d / "cube.sol"));
  EXPECT_TRUE(fs::exists(json));
  // The files as another program reads them.
  const Outcome c = run("certify " + mesh + " --rho0 3 --gamma0 1.5");
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
  // The same cube from an OFF file.
  std::ofstream(d / "cube.off") << cube_off();
  const Outcome o = run("refine --domain " + (d / "cube.off").string() + " --field constant --param m11=16 --param m22=16 --param m33=16 --quiet");
  EXPECT_EQ(o.exit_code, 0) << o.out << o.err;
}

TEST(CliRefine3, BadDomainsAndFieldsGetOneLineAndExit2) {
  const fs::path d = fresh("bad");
  std::ofstream(d / "open.off") << cube_off(false, true);
  std::ofstream(d / "inward.off") << cube_off(true);
  std::ofstream(d / "decimal.off") << cube_off(false, false, "1.1");
  std::ofstream(d / "cube.off") << cube_off();
  const std::string out = (d / "out.mesh").string();
  const struct {
    std::string args, says;
  } cases[] = {
      {"--domain " + (d / "open.off").string(), "the surface is open"},
      {"--domain " + (d / "inward.off").string(), "inward"},
      {"--domain " + (d / "decimal.off").string(), "its x is not exactly a double"},
      {"--domain " + (d / "missing.off").string(), "missing.off"},
      {"--domain cube --algo ls", "meshes polygons only"},
      {"--domain sphere --json " + (d / "c.json").string(), "no such built-in domain"},
      {"--domain cube --field ugawg-polar2", "no metric"},
      {"--domain cube --field constant --param m11=-1", "positive definite"},
  };
  for (const auto& c : cases) {
    const Outcome r = run("refine " + c.args + " --quiet -o " + out);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

// Regression (named after the bug it caught): under UGAWG's linear field at h0 = 0.05 the surface
// level bisected subfacets without flips; thin subfacets in the metric (7°) made every
// tetrahedron on them too skinny for ρ₀ = 3, and the refinement near them cascaded towards the
// face (edges of 10⁻⁷, no end in 120 s). With LEPP–Delaunay (Boundary3's Lawson flips) the run
// ends, consistent and certified, within 3× a unit mesh's tetrahedra (∫√det M = 100 · 20 ln 2 over
// the cube, divided by √2/12, a unit regular tetrahedron's volume: 11,763.1).
TEST(CliRefine3, UgawgLinearAtH0_005IsCertified) {
  const Outcome r = run("refine --domain cube --field ugawg-linear --param h0=0.05 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("stopped: all stars consistent"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\ncertified"), std::string::npos) << r.out;
  const auto at = r.out.find(" tetrahedra in ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const auto from = r.out.rfind(", ", at) + 2;
  const long tetrahedra = std::stol(r.out.substr(from, at - from));
  EXPECT_LT(tetrahedra, 3 * 11763) << r.out;
}

// Regression: the cube-cylinder (UGAWG's, its hollow's 16 strips meeting at reflex ridges of about
// 186°) did not finish under a constant field while the surface was bisected without flips (all
// 3,674 splits of a 60 s run were rule 1's, back and forth across the ridges). Now it ends,
// consistent (every boundary face of the mesh in a plane of Ω's facets) and certified, and its
// file certifies as another program reads it.
TEST(CliRefine3, TheCubeCylinderIsCertified) {
  const fs::path d = fresh("cube_cylinder");
  const std::string mesh = (d / "cc.mesh").string();
  const Outcome r = run("refine --domain cube-cylinder --field constant --param m11=64 --param m22=64 --param m33=64 --quiet -o " + mesh);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("stopped: all stars consistent"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\ncertified"), std::string::npos) << r.out;
  const Outcome c = run("certify " + mesh + " --rho0 3 --gamma0 1.5");
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
}
