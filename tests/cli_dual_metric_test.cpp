// `anisocert dual` and `anisocert metric` as a user runs them. dual: a mesh whose answer is known
// by hand (the square with its centre, identity metrics: the four triangles at the centre are
// the Delaunay triangulation, each dual to the Voronoi vertex at the middle of a side; the two
// halves of the square are not, and the report says why), bad input refused with nothing
// written. metric: the one source of a field's values, so a mesh certified with the .mtr it
// writes gets the same report as with --field; the Gmsh view's layout.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;

const std::string fixtures = std::string(ANISOCERT_REGRESSIONS_DIR) + "/../peers/fixtures/";

fs::path fresh(const std::string& name) { return fresh_folder("cli_dual", name); }

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The unit square's corners and its centre, identity metrics, with `triangles`.
std::string square_with_centre(const fs::path& d, const std::string& triangles) {
  const std::string path = (d / "m.json").string();
  std::ofstream(path) << R"({"sites": [{"x": "0", "y": "0", "metric": ["1", "0", "1"]}, {"x": "1", "y": "0", "metric": ["1", "0", "1"]},
 {"x": "1", "y": "1", "metric": ["1", "0", "1"]}, {"x": "0", "y": "1", "metric": ["1", "0", "1"]},
 {"x": "1/2", "y": "1/2", "metric": ["1", "0", "1"]}], "triangles": )"
                      << triangles << "}\n";
  return path;
}

TEST(CliDual, TheDelaunayTrianglesOfTheSquareAndItsCentreAreTheDual) {
  const fs::path d = fresh("delaunay");
  const std::string mesh = square_with_centre(d, "[[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]");
  const Outcome r = run("dual --quiet " + mesh + " --json " + (d / "d.json").string() + " --svg " + (d / "d.svg").string());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(read(d / "d.json"));
  EXPECT_TRUE(j["is_dual"].get<bool>());
  EXPECT_EQ(j["triangles"]["dual"].get<int>(), 4);
  EXPECT_EQ(j["missing"]["count"].get<int>(), 0);
  EXPECT_EQ(j["input"]["domain_corners"].get<int>(), 4);
  EXPECT_TRUE(j["theorem7"]["preconditions_hold"].get<bool>());  // every arc cut by ∂Ω ends between its sites' corners
  EXPECT_EQ(read(d / "d.svg").rfind("<svg", 0), 0u);
}

TEST(CliDual, TheTwoHalvesOfTheSquareAreNotAndTheReportSaysWhy) {
  const fs::path d = fresh("halves");
  const std::string mesh = square_with_centre(d, "[[0, 1, 2], [0, 2, 3]]");
  const Outcome r = run("dual --quiet " + mesh + " --json " + (d / "d.json").string());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto j = nlohmann::json::parse(read(d / "d.json"));
  EXPECT_FALSE(j["is_dual"].get<bool>());
  EXPECT_EQ(j["triangles"]["not_dual"].get<int>(), 2);
  EXPECT_EQ(j["missing"]["count"].get<int>(), 4);
  // Corners 0 and 1 are nearest together only at the middle of their side, a Voronoi vertex: no arc.
  EXPECT_EQ(j["not_dual"]["first"][0]["why"].get<std::string>(), "the cells of sites 0 and 1 share no Voronoi arc of D|Ω");
}

TEST(CliDual, BadInputIsRefusedAndNothingIsWritten) {
  const fs::path d = fresh("bad");
  const std::string json = (d / "d.json").string();
  // Two triangles meeting at a vertex only: the boundary passes through it twice.
  const std::string bowtie = (d / "bowtie.json").string();
  std::ofstream(bowtie) << R"({"sites": [{"x": "0", "y": "0", "metric": ["1", "0", "1"]}, {"x": "1", "y": "0", "metric": ["1", "0", "1"]},
 {"x": "1", "y": "1", "metric": ["1", "0", "1"]}, {"x": "2", "y": "1", "metric": ["1", "0", "1"]}, {"x": "2", "y": "2", "metric": ["1", "0", "1"]}],
 "triangles": [[0, 1, 2], [2, 3, 4]]})" << "\n";
  const Outcome pinch = run("dual " + bowtie + " --json " + json);
  EXPECT_EQ(pinch.exit_code, 2);
  EXPECT_EQ(pinch.err, "anisocert: " + bowtie + ": the boundary of the triangles passes through vertex 2 twice: it is not one simple loop\n");
  const Outcome no_metric = run("dual " + fixtures + "gmsh-lshape-shock-coarse.msh --json " + json);
  EXPECT_EQ(no_metric.exit_code, 2);
  EXPECT_NE(no_metric.err.find("has no metric"), std::string::npos) << no_metric.err;
  EXPECT_FALSE(fs::exists(json));
  // An output that cannot be written is refused before the diagram is computed: no progress line.
  const Outcome unwritable = run("dual " + fixtures + "freefem-lshape-shock-coarse.msh --field shock --json /nonexistent/dir/d.json");
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_EQ(unwritable.err, "anisocert: cannot write /nonexistent/dir/d.json: No such file or directory\n");
}

TEST(CliMetric, AMeshCertifiedWithTheWrittenMetricGetsTheReportOfTheField) {
  const fs::path d = fresh("mtr");
  const std::string mesh = fixtures + "freefem-lshape-shock-coarse.msh", mtr = (d / "m.mtr").string();
  ASSERT_EQ(run("metric --field shock --param h=0.1 --at " + mesh + " -o " + mtr).exit_code, 0);
  const Outcome by_file = run("certify " + mesh + " --metric " + mtr + " --json " + (d / "a.json").string());
  const Outcome by_field = run("certify " + mesh + " --field shock --param h=0.1 --json " + (d / "b.json").string());
  EXPECT_EQ(by_file.exit_code, 1) << by_file.err;
  EXPECT_EQ(by_field.exit_code, 1) << by_field.err;
  auto a = nlohmann::json::parse(read(d / "a.json")), b = nlohmann::json::parse(read(d / "b.json"));
  a.erase("metric_source"), b.erase("metric_source");
  EXPECT_EQ(a, b);
}

TEST(CliMetric, TheGmshViewHasATensorTriangleForEachHalfCell) {
  const fs::path d = fresh("pos");
  const Outcome r = run("metric --field constant --param m11=2 --param m12=0.5 --param m22=3 --grid 3 -o " + (d / "bg.pos").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string view = read(d / "bg.pos");
  EXPECT_EQ(view.rfind("View \"metric\" {\n", 0), 0u);
  std::size_t tt = 0;
  for (std::size_t at = view.find("\nTT("); at != std::string::npos; at = view.find("\nTT(", at + 1)) ++tt;
  EXPECT_EQ(tt, 18u);  // 3 × 3 cells, two triangles each
  // The first triangle: corners (0, 0), (1/3, 0), (1/3, 1/3) as doubles, written exactly, and the
  // tensor [2 0.5 0; 0.5 3 0; 0 0 5] at each of its three vertices.
  const std::string first = view.substr(view.find("TT("), view.find('\n', view.find("TT(")) - view.find("TT("));
  EXPECT_EQ(first.substr(0, 10), "TT(0,0,0,0");
  const std::string tensor = "2,0.5,0,0.5,3,0,0,0,5";
  EXPECT_NE(first.find("){" + tensor + "," + tensor + "," + tensor + "};"), std::string::npos) << first;
}

TEST(CliMetric, BadInputIsRefusedAndNothingIsWritten) {
  const fs::path d = fresh("metric_bad");
  const std::string pos = (d / "bg.pos").string();
  const Outcome neither = run("metric --field shock -o " + pos);
  EXPECT_EQ(neither.exit_code, 2);
  EXPECT_EQ(neither.err, "anisocert: give one of --at MESH and --grid N\n");
  const Outcome unwritable = run("metric --field shock --grid 2 -o " + pos + " -o /nonexistent/dir/bg.msh");
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_FALSE(fs::exists(pos));
  const Outcome reader = run("certify " + pos + " --field shock");  // the view is written, not read
  EXPECT_EQ(reader.exit_code, 2);
  EXPECT_NE(reader.err.find("anisocert writes gmsh-view files but does not read them"), std::string::npos) << reader.err;
}

}  // namespace
