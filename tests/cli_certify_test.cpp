// `anisocert certify` on meshes from elsewhere, as a user runs it: each format through the same
// checks, the metric checks' verdicts against bounds whose answer is known (a refined mesh's
// lengths all lie in [0, 100]; no triangle has every angle of 90°), the report files, and usage
// errors refused before anything is written.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

namespace fs = std::filesystem;

const std::string peers = std::string(ANISOCERT_REGRESSIONS_DIR) + "/../formats/peers/";

fs::path fresh(const std::string& name) { return fresh_folder("cli_certify", name); }

TEST(CliCertify, MetricChecksAsVerdictsOnARefinedMesh) {
  const fs::path d = fresh("refined");
  const std::string mesh = (d / "m.mesh").string(), sol = (d / "m.sol").string();
  ASSERT_EQ(run("refine --field constant --param m11=20 --param m22=20 --quiet -o " + mesh).exit_code, 0);
  const std::string certify = "certify " + mesh + " --metric " + sol;
  const Outcome wide = run(certify + " --length-range 0 100 --min-quality 0 --json " + (d / "r.json").string() + " --svg " +
                           (d / "r.svg").string());
  EXPECT_EQ(wide.exit_code, 0) << wide.out << wide.err;
  std::ifstream in(d / "r.json");
  const nlohmann::json r = nlohmann::json::parse(in);
  for (const char* key : {"valid", "locally_uniform", "lengths", "quality", "angles"}) EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_TRUE(r["lengths"]["holds"].get<bool>());
  EXPECT_LE(r["lengths"]["unit_edges"].get<int>(), r["lengths"]["edges"].get<int>());
  // The quality enclosures: least <= median, each [lo, hi] with lo <= hi, within [0, 1].
  const auto least = r["quality"]["least"];
  EXPECT_LE(least[0].get<double>(), least[1].get<double>());
  EXPECT_GE(least[0].get<double>(), 0.0);
  EXPECT_LE(least[1].get<double>(), 1.0);
  std::ifstream svg(d / "r.svg");
  std::stringstream s;
  s << svg.rdbuf();
  EXPECT_EQ(s.str().rfind("<svg", 0), 0u);
  // Bounds that fail: every triangle has an angle below 90°, and no edge has length exactly 1.
  const Outcome right = run(certify + " --min-angle 90");
  EXPECT_EQ(right.exit_code, 1);
  EXPECT_NE(right.out.find("every angle >= 90° in its vertex's metric: FAILS"), std::string::npos) << right.out;
  EXPECT_EQ(run(certify + " --length-range 1 1").exit_code, 1);
}

// MMG's convention: BASE.mesh's metric is BASE.sol beside it; the report says where the metrics
// came from, and a bound without any metric is refused rather than skipped.
TEST(CliCertify, TheSolBesideAMeditMeshIsItsMetric) {
  const fs::path d = fresh("beside");
  const std::string mesh = (d / "m.mesh").string();
  ASSERT_EQ(run("refine --field constant --param m11=20 --param m22=20 --quiet -o " + mesh).exit_code, 0);
  const Outcome r = run("certify " + mesh + " --rho0 3 --gamma0 1.5");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("metrics from " + (d / "m.sol").string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("radius-edge ratio ≤ 3 in each vertex's metric: holds"), std::string::npos) << r.out;
  fs::remove(d / "m.sol");
  const Outcome none = run("certify " + mesh + " --rho0 3");
  EXPECT_EQ(none.exit_code, 2) << none.out;
  EXPECT_NE(none.err.find("has no metric, which the requested checks and bounds need"), std::string::npos) << none.err;
  EXPECT_EQ(run("certify " + mesh).exit_code, 0);  // validity alone, said so
  EXPECT_EQ(run("certify " + mesh + " --checks valid,uniform").exit_code, 2);  // asked for explicitly
}

TEST(CliCertify, PeersFilesInEveryFormat) {
  for (const std::string f : {"gmsh/square-hole-41.msh", "gmsh/square-hole-22.msh", "gmsh/square-hole-41-bin.msh",
                              "freefem/square_hole.msh"}) {
    const Outcome r = run("certify " + peers + f);
    EXPECT_EQ(r.exit_code, 0) << f << r.out << r.err;
    EXPECT_NE(r.out.find("valid (a triangulation of the domain, segments are unions of edges): holds"), std::string::npos);
    EXPECT_NE(r.out.find("no metric: only validity was checked"), std::string::npos);
  }
  const Outcome with_metric = run("certify " + peers + "freefem/square_hole.msh --metric " + peers + "freefem/square_hole.mtr");
  EXPECT_NE(with_metric.out.find("edge lengths in their endpoints' metrics: measured"), std::string::npos) << with_metric.out;
}

TEST(CliCertify, ATriangleRemovedFromAPeersMeshLeavesTheDeclaredDomainUncovered) {
  // FreeFem's square with a hole, its first triangle dropped: the boundary of the union gains
  // edges that the file does not declare.
  std::ifstream in(peers + "freefem/square_hole.msh");
  int nv, nt, nbe;
  in >> nv >> nt >> nbe;
  std::string rest, line;
  std::getline(in, line);
  std::ostringstream out;
  out << nv << " " << nt - 1 << " " << nbe << "\n";
  for (int i = 0; i < nv && std::getline(in, line); ++i) out << line << "\n";
  std::getline(in, line);  // the first triangle
  while (std::getline(in, line)) out << line << "\n";
  const fs::path d = fresh("holed");
  std::ofstream(d / "m.msh") << out.str();
  const Outcome r = run("certify " + (d / "m.msh").string() + " --format freefem");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("bounds the union of the cells but is not an edge of the file"), std::string::npos) << r.out;
}

TEST(CliCertify, UsageErrorsWriteNothing) {
  const fs::path d = fresh("usage");
  const std::string mesh = peers + "freefem/square_hole.msh", mtr = peers + "freefem/square_hole.mtr";
  const std::string outputs = " --json " + (d / "r.json").string() + " --svg " + (d / "r.svg").string();
  for (const std::string bad : {" --min-angle 0", " --min-angle 91", " --min-quality 2", " --length-range 2 1",
                                " --field shock", " --checks valid,nonsense", " --format nonsense",
                                // beyond the magnitudes anisocert reads, as in every file (numbers/rational.hpp)
                                " --rho0 1e-2000", " --min-quality 1e-400", " --length-range 0 1e5000"}) {
    const Outcome r = run("certify " + mesh + " --metric " + mtr + bad + outputs);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(d));
}

// A bad mesh from elsewhere has a witness per triangle: --json lists, per list, the exact count and
// the first 100 (a million-triangle mesh gave a 900 MB report before); --all-witnesses lists all,
// in the same order; the text shows three and says how many more.
TEST(CliCertify, ReportsListTheFirstHundredWitnessesAndCountThemAll) {
  const fs::path d = fresh("witnesses");
  const std::string mesh = (d / "m.mesh").string();
  ASSERT_EQ(run("refine --field constant --param m11=400 --param m22=400 --quiet -o " + mesh).exit_code, 0);
  // Certified in a metric stretched 10:1 along x, which the isotropic mesh does not follow.
  const std::string certify = "certify " + mesh + " --field constant --param m11=100 --param m22=1 --rho0 1.5 --json ";
  const auto report = [](const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
  };
  const Outcome first = run(certify + (d / "first.json").string());
  ASSERT_EQ(first.exit_code, 1) << first.out << first.err;
  const Outcome all = run(certify + (d / "all.json").string() + " --all-witnesses");
  ASSERT_EQ(all.exit_code, 1) << all.out << all.err;
  const nlohmann::json f = report(d / "first.json"), a = report(d / "all.json");
  EXPECT_EQ(f["witnesses_listed"], 100);
  EXPECT_TRUE(a["witnesses_listed"].is_null());
  for (const char* check : {"locally_uniform", "radius_edge"}) {
    SCOPED_TRACE(check);
    const std::size_t count = f[check]["violation_count"].get<std::size_t>();
    ASSERT_GT(count, 100u) << "the test needs a mesh with more than 100 failing triangles";
    EXPECT_EQ(a[check]["violation_count"].get<std::size_t>(), count);
    ASSERT_EQ(f[check]["violations"].size(), 100u);
    ASSERT_EQ(a[check]["violations"].size(), count);
    std::set<int> triangles;
    for (std::size_t i = 0; i < count; ++i) {
      if (i < 100) {
        EXPECT_EQ(f[check]["violations"][i], a[check]["violations"][i]) << i;  // the first ones, in order
      }
      triangles.insert(a[check]["violations"][i]["triangle"].get<int>());
    }
    EXPECT_EQ(triangles.size(), count) << "one witness per triangle";
  }
  // The text: three witnesses of each list and the exact number of the others.
  const std::size_t uniform = f["locally_uniform"]["violation_count"].get<std::size_t>();
  EXPECT_NE(first.out.find("… and " + std::to_string(uniform - 3) + " more"), std::string::npos) << first.out;
  EXPECT_EQ(first.out, all.out);
  EXPECT_LT(first.out.size(), 3000u);
}

}  // namespace
