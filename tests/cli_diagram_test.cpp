// `anisocert diagram` and `anisocert demo` as a user runs them: the JSON contract of DESIGN.md,
// exit codes, messages naming the bad site or edge, and no partial output on bad input.
#include "tests/cli_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <tuple>

namespace {

using Json = nlohmann::json;

std::string write_input(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "anisocert_" + std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

const char* kSquare = R"("domain": [["0","0"],["1","0"],["1","1"],["0","1"]])";

TEST(CliDiagram, JsonHasTheDesignFields) {
  const std::string in = write_input("three.json", std::string(R"({"sites": [
      {"x": "0.2", "y": "0.2", "metric": ["1","0","1"]},
      {"x": 0.8, "y": "3/10", "metric": ["2","1/2","1"]},
      {"x": "0.4", "y": "0.8", "metric": [1, 0, 4]}], )") + kSquare + "}");
  const std::string out = in + ".out.json", svg = in + ".svg";
  const Outcome r = run("diagram " + in + " --json " + out + " --svg " + svg + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Theorem 7 preconditions: do not hold"), std::string::npos) << r.out;
  std::ifstream f(out);
  const Json j = Json::parse(f);
  for (const char* key : {"vertices", "arcs", "faces", "dual", "theorem7", "counts"}) EXPECT_TRUE(j.contains(key)) << key;
  int voronoi = 0;
  for (const Json& v : j["vertices"]) {
    for (const char* key : {"id", "sites", "x", "y", "on_domain_boundary", "wedged"}) EXPECT_TRUE(v.contains(key)) << key;
    if (v["kind"] == "voronoi") {
      ++voronoi;
      EXPECT_EQ(v["sites"], Json({0, 1, 2}));
    }
  }
  EXPECT_EQ(voronoi, 1);
  EXPECT_EQ(j["counts"]["vertices"], 1);
  EXPECT_EQ(j["counts"]["faces"], 3);
  for (const Json& a : j["arcs"])
    for (const char* key : {"id", "sites", "vertices", "closed", "cut_by_domain", "wedged", "witness"})
      EXPECT_TRUE(a.contains(key)) << key;
  ASSERT_EQ(j["dual"]["triangles"].size(), 1u);
  EXPECT_FALSE(j["dual"]["is_triangulation"]);  // the corners are not sites
  EXPECT_FALSE(j["theorem7"]["preconditions_hold"]);
  std::ifstream s(svg);
  const std::string picture((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
  EXPECT_EQ(picture.rfind("<svg", 0), 0u);
  EXPECT_NE(picture.find("</svg>"), std::string::npos);
}

// The filter statistics the summary and stats.filters report, pinned on one small input (four
// sites, the default domain, one thread): signs decided by intervals 62, exactly 12. They count the
// work the filters did, so they pin it: the interval shortcut of Builder::nearest ("u is strictly
// farther") decides without a sign; without it an independent reader's simulation counted 74 / 12,
// the same diagram otherwise (the 2026-11-30 campaign's mutant 32, told apart on 2026-12-03).
// A change that meets this test on purpose updates the figures, with the reason.
TEST(CliDiagram, FilterStatisticsArePinnedOnFourSites) {
  const std::string in = write_input("four.json", R"({"sites": [{"x": "0", "y": "0", "metric": ["1", "0", "1"]},
      {"x": "1", "y": "0", "metric": ["2", "0", "1"]}, {"x": "0", "y": "1", "metric": ["1", "0", "3"]},
      {"x": "3/4", "y": "4/5", "metric": ["1", "0", "1"]}]})");
  const std::string out = in + ".out.json";
  const Outcome r = run("diagram " + in + " --threads 1 --quiet --json " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("signs 62 / 12"), std::string::npos) << r.out;
  std::ifstream f(out);
  const Json j = Json::parse(f);
  EXPECT_EQ(j["stats"]["filters"]["signs"]["filtered"], 62);
  EXPECT_EQ(j["stats"]["filters"]["signs"]["exact"], 12);
}

TEST(CliDiagram, BadInputNamesTheProblemAndWritesNothing) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"sites": [{"x": "0.5", "y": "0.5", "metric": ["1","0","1"]},
                     {"x": "1/2", "y": "0.5", "metric": ["2","0","2"]}], )" + std::string(kSquare) + "}",
       "coincide"},
      {R"({"sites": [{"x": "2", "y": "0.5", "metric": ["1","0","1"]}], )" + std::string(kSquare) + "}", "sites[0]"},
      {R"({"sites": [{"x": "0.5", "y": "0.5", "metric": ["1","2","1"]}], )" + std::string(kSquare) + "}",
       "sites[0].metric"},
      {R"({"sites": [{"x": "0.5", "y": "0.5", "metric": ["1","0","1"]}],
          "domain": [["0","0"],["0","1"],["1","1"],["1","0"]]})",
       "clockwise"},
      {R"({"sites": [{"x": "0.5", "y": "0.25", "metric": ["1","0","1"]}],
          "domain": [["0","0"],["1","1"],["1","0"],["0","1"]]})",
       "edge"},
      {"{\"sites\": [}", "invalid JSON"}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    const std::string in = write_input("bad" + std::to_string(i) + ".json", cases[i].first);
    const std::string out = in + ".out.json";
    const Outcome r = run("diagram " + in + " --json " + out + " --quiet");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(cases[i].second), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  EXPECT_EQ(run("diagram /nonexistent/sites.json").exit_code, 2);
}

TEST(CliDiagram, DemoWritesItsPicture) {
  const std::string svg = ::testing::TempDir() + "anisocert_demo_" + std::to_string(getpid()) + ".svg";
  const Outcome r = run("demo --quiet --svg " + svg);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("49 sites"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(svg));
  // The refined mesh is certified exactly, with parameters meeting every decided condition of
  // LU Theorem 4.5.
  EXPECT_NE(r.out.find(": certified"), std::string::npos) << r.out;
  const auto conditions = r.out.find("LU Theorem 4.5 conditions");
  ASSERT_NE(conditions, std::string::npos);
  const std::string line = r.out.substr(conditions, r.out.find('\n', conditions) - conditions);
  EXPECT_EQ(line.find(" no"), std::string::npos) << line;
}

}  // namespace

namespace {

// `anisocert refine` then `anisocert certify`, as a user runs them: exit codes 0, 1 (with the
// offending triangle named), 2; the Medit files hold the same mesh as the JSON file.
TEST(CliMesh, RefineThenCertify) {
  const std::string base = ::testing::TempDir() + "anisocert_mesh_" + std::to_string(getpid());
  const std::string field = "refine --field constant --param m11=20 --param m22=20 --quiet -o " + base;
  const Outcome r = run(field + ".mesh");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("all stars consistent"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(base + ".sol"));
  const Outcome medit = run("certify " + base + ".mesh --metric " + base + ".sol --rho0 3 --gamma0 1.5");
  EXPECT_EQ(medit.exit_code, 0) << medit.out << medit.err;
  ASSERT_EQ(run(field + ".json").exit_code, 0);
  const Outcome c = run("certify " + base + ".json --rho0 3 --gamma0 1.5");
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("certified"), std::string::npos);
  // The same mesh from both files: the same verdicts, line for line after the first (which names
  // the files).
  EXPECT_EQ(c.out.substr(c.out.find('\n')), medit.out.substr(medit.out.find('\n')));
  // Reverse the first triangle: no longer a triangulation.
  std::ifstream in(base + ".json");
  Json mesh = Json::parse(in);
  auto& t = mesh["triangles"][0];
  std::swap(t[0], t[1]);
  std::ofstream(base + "_bad.json") << mesh.dump();
  const Outcome bad = run("certify " + base + "_bad.json");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.out.find("triangle 0"), std::string::npos) << bad.out;
  EXPECT_EQ(run("certify /nonexistent/mesh.json").exit_code, 2);
  EXPECT_EQ(run("refine --field spiral").exit_code, 2);
  EXPECT_EQ(run("refine --gamma0 0.5").exit_code, 2);
  // Each of the star refiner's parameters just outside its range (LU §4.1: ρ₀ > 0, γ₀ > 1,
  // 0 < δ < 1, β > 0; a size > 0) is refused by name, with nothing written.
  for (const char* bad : {"--rho0 0", "--rho0 -1", "--gamma0 1", "--delta 0", "--delta 1", "--beta 0", "--beta -2", "--size 0",
                          "--size -1"}) {
    const Outcome r = run(std::string("refine --quiet -o ") + base + "_never.json " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find(std::string(bad) + " is out of range"), std::string::npos) << bad << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(base + "_never.json")) << bad;
  }
}

// `refine --algo ls --normalized-metric` (LS §9's variation): the report says so, and the mesh's
// metrics are M′ = det(M)^(−1/2) M, here of M = diag(20, 80): diag(1/2, 2), exact in doubles. A flag
// of another refiner is refused by name with exit 2. The picture's caption names the flag: the
// diagram drawn is that of M′, not of the field.
TEST(CliMesh, NormalizedMetricWritesMPrime) {
  const std::string base = ::testing::TempDir() + "anisocert_normalized_" + std::to_string(getpid());
  const Outcome r = run("refine --algo ls --field constant --param m11=20 --param m22=80 --size 0.5 --normalized-metric --quiet -o " + base +
                        ".json --svg " + base + ".svg");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("normalized metric (LS §9)"), std::string::npos) << r.out;
  std::ifstream picture(base + ".svg");
  const std::string svg{std::istreambuf_iterator<char>(picture), std::istreambuf_iterator<char>()};
  EXPECT_NE(svg.find("ls refiner, field constant --normalized-metric: "), std::string::npos);
  std::ifstream in(base + ".json");
  const Json mesh = Json::parse(in);
  ASSERT_FALSE(mesh["sites"].empty());
  for (const auto& site : mesh["sites"]) EXPECT_EQ(site["metric"].dump(), "[\"0.5\",\"0\",\"2\"]");
  const Outcome star = run("refine --normalized-metric --quiet -o " + base + "_never.json");
  EXPECT_EQ(star.exit_code, 2);
  EXPECT_NE(star.err.find("--normalized-metric is not a parameter of --algo star"), std::string::npos) << star.err;
  EXPECT_FALSE(std::filesystem::exists(base + "_never.json"));
}

// The LS refiner on a background-mesh field (an earlier LS mesh of the linear field, its metrics
// interpolated P1), written as Medit .mesh/.sol, with --svg: the picture is the exact D|Ω of the
// final sites with its dual, every arc of it drawn (as many as `anisocert dual` counts in the mesh
// read back), and the mesh its dual, which `dual` confirms from the Medit files, and from Gmsh's
// when written as .msh. Triangle's files hold no metric, and the summary says how to check instead.
// The star refiner's picture is its mesh (no arcs).
TEST(CliMesh, LsOnABackgroundMeshDrawsTheExactDiagram) {
  const std::string base = ::testing::TempDir() + "anisocert_ls_background_" + std::to_string(getpid());
  const Outcome bg = run("refine --algo ls --field linear --param hx=0.5 --param h0=0.125 --size 0.5 --quiet -o " + base + "_bg.json");
  ASSERT_EQ(bg.exit_code, 0) << bg.out << bg.err;
  const Outcome r = run("refine --algo ls --field background:" + base + "_bg.json --size 0.3 --quiet -o " + base + ".mesh --svg " + base + ".svg");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("(the exact D|Ω of the final sites with its dual; the mesh is its dual)"), std::string::npos) << r.out;
  std::ifstream s(base + ".svg");
  const std::string picture((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
  EXPECT_NE(picture.find("its dual (dashed): the mesh is its dual"), std::string::npos);
  std::size_t arcs = 0;
  for (std::size_t at = picture.find("<title>arc "); at != std::string::npos; at = picture.find("<title>arc ", at + 1)) ++arcs;
  const Outcome dual = run("dual " + base + ".mesh --quiet");
  ASSERT_EQ(dual.exit_code, 0) << dual.out << dual.err;
  EXPECT_NE(dual.out.find("metrics from " + base + ".sol"), std::string::npos) << dual.out;
  EXPECT_GT(arcs, 0u);
  EXPECT_NE(dual.out.find(", " + std::to_string(arcs) + " arcs, 0 orphans"), std::string::npos) << arcs << " arcs drawn\n" << dual.out;

  // Gmsh's .msh keeps the metrics ($NodeData) too; Triangle's files hold none, and the summary says so.
  const Outcome gmsh = run("refine --algo ls --field background:" + base + "_bg.json --size 0.3 --quiet -o " + base + ".msh");
  ASSERT_EQ(gmsh.exit_code, 0) << gmsh.err;
  EXPECT_EQ(run("dual " + base + ".msh --quiet").exit_code, 0);
  const Outcome triangle = run("refine --algo ls --field background:" + base + "_bg.json --size 0.3 --quiet -o " + base + ".node");
  ASSERT_EQ(triangle.exit_code, 0) << triangle.err;
  EXPECT_NE(triangle.out.find("(its files hold no metrics: write .json, .mesh or .msh to check it with anisocert dual)"), std::string::npos)
      << triangle.out;

  const Outcome star = run("refine --field constant --max-vertices 40 --quiet --svg " + base + "_star.svg");
  ASSERT_LE(star.exit_code, 1) << star.err;
  std::ifstream t(base + "_star.svg");
  const std::string mesh_picture((std::istreambuf_iterator<char>(t)), std::istreambuf_iterator<char>());
  EXPECT_NE(mesh_picture.find("star refiner, field constant"), std::string::npos);
  EXPECT_EQ(mesh_picture.find("<title>arc "), std::string::npos);
}

// `refine --domain` with the rest of a PSLG (io/mesh_json.hpp: "points", "interior_segments"): a
// slit y = ½ from x = ¼ to ¾ and a point below it. The LS refiner's mesh has every input vertex as
// a site, and the certifier finds its segments (the slit's pieces among them) unions of edges and
// the mesh a triangulation of the square. The star refiner refuses interior features by name, and
// so does every refiner a PSLG whose segments cross; exit 2, nothing written.
TEST(CliMesh, RefineTakesAPslg) {
  const std::string base = ::testing::TempDir() + "anisocert_pslg_" + std::to_string(getpid());
  std::ofstream(base + "_slit.json") << R"({"domain": [[0,0],[1,0],[1,1],[0,1]], "points": [[0.25,0.5],[0.75,0.5],[0.5,0.25]],
                                           "interior_segments": [[4,5]]})";
  const Outcome r = run("refine --algo ls --field constant --size 0.25 --quiet --domain " + base + "_slit.json -o " + base + ".json");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::ifstream in(base + ".json");
  const Json mesh = Json::parse(in);
  for (const auto& [k, x, y] : {std::tuple{4, "0.25", "0.5"}, std::tuple{5, "0.75", "0.5"}, std::tuple{6, "0.5", "0.25"}}) {
    EXPECT_EQ(mesh["sites"][k]["x"], x);
    EXPECT_EQ(mesh["sites"][k]["y"], y);
  }
  std::size_t on_slit = 0;
  for (const auto& s : mesh["segments"])
    on_slit += mesh["sites"][s[0].get<int>()]["y"] == "0.5" && mesh["sites"][s[1].get<int>()]["y"] == "0.5";
  EXPECT_GE(on_slit, 2u);
  const Outcome c = run("certify " + base + ".json");
  EXPECT_NE(c.out.find("valid (a triangulation of the domain, segments are unions of edges): holds"), std::string::npos) << c.out;

  const Outcome star = run("refine --quiet --domain " + base + "_slit.json -o " + base + "_never.json");
  EXPECT_EQ(star.exit_code, 2);
  EXPECT_NE(star.err.find("--algo star keeps no interior segments (LU §4.1 protects ∂Ω only)"), std::string::npos) << star.err;
  std::ofstream(base + "_cross.json") << R"({"domain": [[0,0],[1,0],[1,1],[0,1]],
      "points": [[0.25,0.5],[0.75,0.5],[0.5,0.25],[0.5,0.75]], "interior_segments": [[4,5],[6,7]]})";
  const Outcome cross = run("refine --algo ls --quiet --domain " + base + "_cross.json -o " + base + "_never.json");
  EXPECT_EQ(cross.exit_code, 2);
  EXPECT_NE(cross.err.find("interior segment 1 from point 2 (0.5, 0.25) to point 3 (0.5, 0.75) meets interior segment 0"),
            std::string::npos) << cross.err;
  EXPECT_EQ(std::count(cross.err.begin(), cross.err.end(), '\n'), 1);
  EXPECT_FALSE(std::filesystem::exists(base + "_never.json"));
}

}  // namespace

// What a new user's trial of `refine --algo ls` found (2026-12-02), each refused with exit 2, one
// line naming the problem, before the run and with nothing written: a directory given as an input
// file (was an internal error, exit 3, in refine, certify and dual); budgets that are not positive
// (--max-vertices -5 ran without a budget, --max-seconds -1 stopped at once and wrote a mesh); a
// seed for a refiner that draws no random points; a --param given twice (the second won
// silently); an output folder that does not exist (refused only after the whole run); a
// background metric file of an unknown extension (the message named --metric-format, which
// refine does not have); and an interior segment repeating a vertex (the message named "sites",
// a key the domain file does not have). Fractions are read wherever the docs say numbers are.
TEST(CliMesh, RefineRefusesBadInputBeforeTheRun) {
  const std::string base = ::testing::TempDir() + "anisocert_refine_bad_" + std::to_string(getpid());
  std::filesystem::create_directories(base + "_dir.json");
  std::ofstream(base + "_seg.json") << R"({"domain": [[0,0],[1,0],[1,1],[0,1]], "interior_segments": [[0,0]]})";
  std::ofstream(base + "_bg.json") << R"({"sites": [{"x": "0", "y": "0", "metric": ["1","0","1"]}, {"x": "1", "y": "0", "metric": ["1","0","1"]},
                                                    {"x": "0", "y": "1", "metric": ["1","0","1"]}], "triangles": [[0, 1, 2]]})";
  const std::string never = base + "_never.json";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"refine --algo ls --domain " + base + "_dir.json -o " + never, "it is a directory"},
      {"refine --algo ls --field background:" + base + "_dir.json -o " + never, "it is a directory"},
      {"certify " + base + "_dir.json", "it is a directory"},
      {"dual " + base + "_dir.json", "it is a directory"},
      {"refine --algo ls --max-vertices -5 -o " + never, "--max-vertices \"-5\": expected a positive whole number"},
      {"refine --algo ls --max-vertices 2.5 -o " + never, "--max-vertices \"2.5\": expected a positive whole number"},
      {"refine --algo ls --max-seconds -1 -o " + never, "--max-seconds \"-1\": expected a positive number"},
      {"refine --algo ls --max-seconds 0 -o " + never, "--max-seconds \"0\": expected a positive number"},
      {"refine --algo ls --seed 3 -o " + never, "--seed is not a parameter of --algo ls"},
      {"refine --algo ls --param alpha=1 --param alpha=2 -o " + never, "--param \"alpha\" is given twice"},
      {"refine --algo ls -o /nonexistent/x.json", "cannot write /nonexistent/x.json"},
      {"refine --algo ls -o " + base + ".xyz", "no mesh format has the extension"},
      {"refine --algo ls --output-format bogus -o " + never, "unknown mesh format"},
      {"refine --algo ls --size 1e-330 -o " + never, "is below the range of doubles"},
      {"refine --algo ls --field background:" + base + "_bg.json:" + base + "_bg.json -o " + never, "is not a metric file"},
      {"refine --algo ls --domain " + base + "_seg.json -o " + never, "interior_segments[0]: repeats vertex 0"}};
  for (const auto& [args, why] : cases) {
    const Outcome r = run(args.rfind("certify", 0) == 0 ? args : args + " --quiet");  // certify prints no progress
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_FALSE(std::filesystem::exists(never)) << args;
  }
  const Outcome fractions = run("refine --algo ls --field constant --size 1/3 --theta-bound 40/3 --max-seconds 30/2 --quiet -o " + base + ".json");
  EXPECT_EQ(fractions.exit_code, 0) << fractions.err;
  EXPECT_NE(fractions.out.find("θ_bound = 13.3333°, size = 0.333333"), std::string::npos) << fractions.out;
  EXPECT_NE(fractions.out.find("check it with anisocert dual"), std::string::npos) << fractions.out;
}

// `refine --algo bwy` (issue 17) as a user runs it: the shock field, written as Medit files with a
// picture of the exact diagram; the report names its stop (no rule of BWY §3.2.2 applies) and
// decides §4.2's conditions for the run's B and G (the default G is the largest of Lemma 2 for
// B = 1.5 rounded down: (G² − 1)(1 + G)²(1 + 4G)² 1.5⁴ is at most 1 at 1.000984645 and above 1 at
// 1.000984646, in exact fractions, Python's fractions module); `dual` confirms the mesh read
// back from the Medit files. Each parameter just outside its range is refused by name with exit 2
// and nothing written, as is another refiner's parameter.
TEST(CliMesh, BwyRefinesTheShockFieldAndDualConfirmsIt) {
  const std::string base = ::testing::TempDir() + "anisocert_bwy_" + std::to_string(getpid());
  const Outcome r = run("refine --algo bwy --field shock --size 8 --quiet -o " + base + ".mesh --svg " + base + ".svg");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("stopped: no rule of BWY §3.2.2 applies"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("BWY §4.2 (decided exactly) for B = 1.5, G = 1.000984645: Lemma 2 holds, G²√(G⁴−1) ≤ 1 holds, G²√(G²+1) ≤ B holds"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("check it with anisocert dual"), std::string::npos) << r.out;
  std::ifstream s(base + ".svg");
  const std::string picture((std::istreambuf_iterator<char>(s)), std::istreambuf_iterator<char>());
  EXPECT_NE(picture.find("bwy refiner, field shock"), std::string::npos);
  EXPECT_NE(picture.find("its dual (dashed): the mesh is its dual"), std::string::npos);
  const Outcome dual = run("dual " + base + ".mesh --quiet");
  EXPECT_EQ(dual.exit_code, 0) << dual.out << dual.err;
  EXPECT_NE(dual.out.find("the mesh is the dual of the anisotropic Voronoi diagram of its vertices"), std::string::npos) << dual.out;
  for (const char* bad : {"--shape-bound 1", "--shape-bound 0.5", "--distortion 0.5", "--size -1"}) {
    const Outcome refused = run(std::string("refine --algo bwy --quiet -o ") + base + "_never.json " + bad);
    EXPECT_EQ(refused.exit_code, 2) << bad;
    EXPECT_NE(refused.err.find(std::string(bad) + " is out of range"), std::string::npos) << bad << ": " << refused.err;
    EXPECT_FALSE(std::filesystem::exists(base + "_never.json")) << bad;
  }
  // LS's θ_bound must lie in (0°, 60°): each end is refused on its own (a campaign survivor
  // accepted every value), nothing written.
  for (const char* bad : {"--theta-bound 60", "--theta-bound 0", "--theta-bound -5", "--size -1"}) {
    const Outcome refused = run(std::string("refine --algo ls --quiet -o ") + base + "_never.json " + bad);
    EXPECT_EQ(refused.exit_code, 2) << bad;
    EXPECT_NE(refused.err.find(std::string(bad) + " is out of range"), std::string::npos) << bad << ": " << refused.err;
    EXPECT_FALSE(std::filesystem::exists(base + "_never.json")) << bad;
  }
  const Outcome ls_parameter = run("refine --algo bwy --theta-bound 20 --quiet -o " + base + "_never.json");
  EXPECT_EQ(ls_parameter.exit_code, 2);
  EXPECT_NE(ls_parameter.err.find("--theta-bound is not a parameter of --algo bwy"), std::string::npos) << ls_parameter.err;
  EXPECT_FALSE(std::filesystem::exists(base + "_never.json"));
  // Found by a new user's trial: FreeFem's files, whose .mtr `dual` does not find by itself, got
  // the hint "check it with anisocert dual", which refused them; the hint is now the command.
  const Outcome freefem = run("refine --algo bwy --field shock --size 8 --quiet -o " + base + "_ff.msh --output-format freefem");
  ASSERT_EQ(freefem.exit_code, 0) << freefem.err;
  const std::string check = "anisocert dual " + base + "_ff.msh --metric " + base + "_ff.mtr";
  EXPECT_NE(freefem.out.find("(check it with " + check + ")"), std::string::npos) << freefem.out;
  EXPECT_EQ(run(check.substr(std::string("anisocert ").size()) + " --quiet").exit_code, 0);
  // …and a stopped run's picture said "the mesh is its dual" of a dual with flat and overlapping
  // triangles, which `dual` refuses to read: the caption says it is no triangulation.
  const Outcome stopped = run("refine --algo bwy --field shock --param h=0.02 --max-vertices 200 --quiet -o " + base + "_stopped.json --svg " +
                              base + "_stopped.svg");
  EXPECT_EQ(stopped.exit_code, 1) << stopped.err;
  EXPECT_NE(stopped.out.find("the mesh is its dual, which is no triangulation of Ω)"), std::string::npos) << stopped.out;
}

// BWY §3.2.2 applies one rule per step, in its order. Two mutants of the 2026-12-02 campaign (141,
// 153) broke the order where no test looked; both runs are a second reader's (helper) inputs.
TEST(CliMesh, BwyAppliesOneRulePerStepInTheOrderOfSection322) {
  const std::string base = ::testing::TempDir() + "anisocert_bwy_order_" + std::to_string(getpid());
  // A 1 × 1/4 rectangle: the first step attacks the corners' unresolved place, which becomes a
  // split; with a budget of 5 vertices (4 corners + 1) the run makes exactly that one insertion,
  // and the side it split is left encroached for rule 1, not taken by rule 2 in the same step.
  std::ofstream(base + "_thin.json") << R"({"domain": [["0","0"],["1","0"],["1","0.25"],["0","0.25"]]})";
  const Outcome thin = run("refine --algo bwy --field radial --domain " + base + "_thin.json --size 0.5 --max-vertices 5 --quiet -o " + base + "_thin_out.json");
  EXPECT_EQ(thin.exit_code, 1) << thin.err;
  EXPECT_NE(thin.out.find("last insertion by rule: split instead; encroached subsegments: 1"), std::string::npos) << thin.out;
  std::ifstream written(base + "_thin_out.json");
  EXPECT_EQ(Json::parse(written)["sites"].size(), 5u);
  // Four sites in a square of side 1/2 with one metric (h = 0.5 gives 4·I away from the thin ring
  // r = R) make an exact tie at (1/2, 1/2), no bad shape: its radius-edge ratio is √2/2 in that
  // metric, far below B = 100. A fifth site on the ring (metric 100 times stronger across it)
  // makes Voronoi vertices whose triangles overlap the tie's fan. After the four splits of Ω's
  // sides (rule 1), the first insertion is rule 4's (several vertices), never rule 3's.
  std::ofstream(base + "_tie.json") << R"({"domain": [["-1","-1"],["2","-1"],["2","2"],["-1","2"]],
    "points": [["0.25","0.25"],["0.75","0.25"],["0.75","0.75"],["0.25","0.75"],["0.5","0.265625"]]})";
  const std::string tie = "refine --algo bwy --domain " + base + "_tie.json --field radial --param h=0.5 --param delta=0.001 --param R=0.234375 "
                          "--shape-bound 100 --size 0 --quiet -o " + base + "_tie_out.json";
  const Outcome first = run(tie + " --max-vertices 14");
  EXPECT_EQ(first.exit_code, 1) << first.err;
  EXPECT_NE(first.out.find("insertions by rule: corner shell 0, encroached segment 4, unresolved 0, not an edge 0, split instead 0, bad shape 0, several vertices 1,"),
            std::string::npos) << first.out;
  const Outcome whole = run(tie);
  EXPECT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_NE(whole.out.find("bad shape 0, several vertices"), std::string::npos) << whole.out;
  EXPECT_EQ(whole.out.find("overlap 0,"), std::string::npos) << whole.out;
}
