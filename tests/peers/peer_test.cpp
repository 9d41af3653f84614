// Real peers (issue 15; docs/validation.md): Gmsh's BAMG, FreeFem++'s adaptmesh and BAMG's own
// command line mesh the unit square and an L-shape for the built-in fields, at two sizes, as their
// users adapt (scripts/validate), and anisocert certifies each mesh exactly. What is asserted of a
// peer's mesh is what any mesher aiming at unit length owes, with bounds justified below; exact
// counts of a peer's output are never asserted (Gmsh is not deterministic here). The fixtures
// (tests/peers/fixtures/README.md) keep the rotated-metric finding testable if a peer changes.
#include "fields/registry.hpp"
#include "tests/cli_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string source_dir = ANISOCERT_SOURCE_DIR;
const std::string fixtures = source_dir + "/tests/peers/fixtures/";

struct Peer {
  std::string peer, domain, field, size;
};

std::string test_name(const Peer& p) { return p.peer + "_" + p.domain + "_" + p.field + "_" + p.size; }

// How GoogleTest (and CTest's test names) print a case.
[[maybe_unused]] void PrintTo(const Peer& p, std::ostream* o) { *o << test_name(p); }

// The field parameters of the two sizes: the default field ("fine") and one twice as coarse.
std::vector<std::string> size_params(const Peer& p) {
  if (p.field == "linear") return p.size == "fine" ? std::vector<std::string>{} : std::vector<std::string>{"hx=0.2", "h0=0.002"};
  return {p.size == "fine" ? "h=0.05" : "h=0.1"};
}

std::string param_args(const std::vector<std::string>& params) {
  std::string s;
  for (const auto& kv : params) s += " --param " + kv;
  return s;
}

std::string fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("anisocert_peer_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d.string();
}

Json read_json(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "no " << path;
  return in.good() ? Json::parse(in) : Json();
}

// scripts/validate with the anisocert under test.
Outcome validate(const std::string& args, const std::string& env = "") {
  return run_command(env + " ANISOCERT=" + std::string(ANISOCERT_BIN) + " bash " + source_dir + "/scripts/validate " + args);
}

double unit_share(const Json& c) {
  return c["lengths"]["unit_edges"].get<double>() / c["lengths"]["edges"].get<double>();
}

double median_quality(const Json& c) {
  for (const auto& q : c["quality"]["quantiles"])
    if (q["p"].get<double>() == 0.5) return q["enclosure"][0].get<double>();
  ADD_FAILURE() << "no median quality";
  return 0;
}

// The vertices of a unit mesh of the domain for a field: a triangle with unit edges in M has area
// (√3/4)/√det M, so a unit mesh has about ∫ √det M / (√3/4) triangles and half as many vertices
// (Euler's formula, boundary neglected). The integral by the midpoint rule on a 400 × 400 grid of
// the field as anisocert evaluates it (fields/): a figure independent of any peer.
double unit_mesh_vertices(const std::string& field, const std::vector<std::string>& params, const std::string& domain) {
  anisocert::fields::Parameters given;
  for (const auto& kv : params) given[kv.substr(0, kv.find('='))] = std::stod(kv.substr(kv.find('=') + 1));
  const auto f = anisocert::fields::make_field(field, given);
  constexpr int n = 400;
  double area = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) / n, y = (j + 0.5) / n;
      if (domain == "lshape" && x > 0.5 && y > 0.5) continue;
      const auto M = f.at(x, y);
      area += std::sqrt(M.m11 * M.m22 - M.m12 * M.m12) / (n * n);
    }
  return area / (std::sqrt(3.0) / 4) / 2;
}

class PeerMesh : public ::testing::TestWithParam<Peer> {};

// Every peer, domain, field and size:
//  - the mesh is valid: a triangulation of the domain is what every mesher promises, and the
//    certifier decides it exactly;
//  - its vertex count is within a factor 3 of a unit mesh's (unit_mesh_vertices), 6 for Gmsh: a
//    peer that ignored the metric, or read it squared, is off by far more. Gmsh's mishandling of
//    rotated metrics (RotatedConstantMetric below) inflates its meshes up to 5 times where the
//    field's directions are not axis-aligned (first run: bamg 1.0 to 1.3 times, FreeFem 1.1 to
//    1.9, Gmsh 1.2 to 3.0; the test prints each figure);
//  - the share of edges of unit length in both endpoints' metrics is above a floor. On `linear`
//    (a diagonal metric, the axis-aligned case BAMG handles best) at least 80% for every peer
//    (first run: 85–99%). On `shock` and `radial`, whose principal directions turn, at least 35%
//    (first run: Gmsh 45–53%, FreeFem 47–78%, bamg higher): a metric evaluated at the wrong
//    vertices, or not re-evaluated between rounds, gives far less.
TEST_P(PeerMesh, IsValidNearAUnitMeshAndAboveItsUnitEdgeFloor) {
  const Peer& p = GetParam();
  const auto params = size_params(p);
  const std::string out = fresh_dir(test_name(p));
  const Outcome r = validate("--peer " + p.peer + " --domain " + p.domain + " --field " + p.field + param_args(params) + " --out " + out);
  ASSERT_LE(r.exit_code, 1) << r.err;
  const Json c = read_json(out + "/certify.json");
  ASSERT_FALSE(c.is_null());
  EXPECT_TRUE(c["valid"]["holds"].get<bool>()) << r.out;
  const double expected = unit_mesh_vertices(p.field, params, p.domain), vertices = c["vertices"].get<double>();
  std::printf("%s: %.0f vertices, %.2f times a unit mesh's %.0f; %.1f%% unit edges\n", test_name(p).c_str(), vertices,
              vertices / expected, expected, 100 * unit_share(c));
  EXPECT_GT(vertices, expected / 3) << r.out;
  EXPECT_LT(vertices, expected * (p.peer == "gmsh" ? 6 : 3)) << r.out;
  EXPECT_GE(unit_share(c), p.field == "linear" ? 0.8 : 0.35) << r.out;
  fs::remove_all(out);
}

std::vector<Peer> matrix() {
  std::vector<Peer> m;
  for (const char* peer : {"gmsh", "freefem", "bamg"})
    for (const char* domain : {"square", "lshape"})
      for (const char* field : {"shock", "radial", "linear"})
        for (const char* size : {"coarse", "fine"}) m.push_back({peer, domain, field, size});
  return m;
}

INSTANTIATE_TEST_SUITE_P(Peers, PeerMesh, ::testing::ValuesIn(matrix()),
                         [](const ::testing::TestParamInfo<Peer>& i) { return test_name(i.param); });

// A constant metric with eigenvalues 100 and 10⁴ whose long axis (eigenvalue 100) makes `degrees`
// with the x-axis: M = R diag(100, 10⁴) Rᵀ, as --param values (the shortest decimals of its doubles).
std::string rotated_metric(double degrees) {
  const double t = degrees * std::acos(-1.0) / 180, c = std::cos(t), s = std::sin(t);
  char buf[200];
  std::snprintf(buf, sizeof buf, "--param m11=%.17g --param m12=%.17g --param m22=%.17g", 100 * c * c + 1e4 * s * s,
                (100 - 1e4) * c * s, 100 * s * s + 1e4 * c * c);
  return buf;
}

// A constant metric has an exact unit mesh (the image of an equilateral lattice: every edge of
// length 1, every quality 1), of about ∫ √det M / (√3/4) / 2 = 1000 / (√3/4) / 2 ≈ 1155 vertices
// on the unit square at any angle. So for a correct mesher the figures cannot depend on the angle.
// FreeFem++ and bamg at 20°: at least 90% unit edges, median quality at least 0.9, at most twice
// 1155 vertices (first run: 99%, 0.997, about 1,560). Gmsh at 0° (axis-aligned) likewise.
TEST(RotatedConstantMetric, FreeFemAndBamgMeshItAtAnyAngleAndGmshAxisAligned) {
  for (const auto& [peer, degrees] : std::vector<std::pair<std::string, double>>{{"freefem", 20}, {"bamg", 20}, {"gmsh", 0}}) {
    SCOPED_TRACE(peer + " at " + std::to_string(degrees) + " degrees");
    const std::string out = fresh_dir(peer + "_rotated");
    const Outcome r = validate("--peer " + peer + " --field constant " + rotated_metric(degrees) + " --grid 10 --out " + out);
    ASSERT_LE(r.exit_code, 1) << r.err;
    const Json c = read_json(out + "/certify.json");
    EXPECT_TRUE(c["valid"]["holds"].get<bool>());
    EXPECT_GE(unit_share(c), 0.9) << r.out;
    EXPECT_GE(median_quality(c), 0.9) << r.out;
    EXPECT_LT(c["vertices"].get<double>(), 2 * 1155.0) << r.out;
    fs::remove_all(out);
  }
}

// The same field at 20° as Gmsh 4.8.4 meshed it (fixtures/gmsh-constant-20deg.msh) against
// FreeFem's and bamg's meshes of it (fixtures/*-constant-20deg.msh): the certifier's conformity
// figures tell the rotated-metric failure apart. Gmsh's mesh has under 70% unit edges, a median
// quality under 0.5 and over three times a unit mesh's vertices; the others pass the bounds above.
TEST(RotatedConstantMetric, CertifierTellsGmshsRotatedMetricMeshApartFromCorrectOnes) {
  for (const std::string peer : {"gmsh", "freefem", "bamg"}) {
    SCOPED_TRACE(peer);
    const std::string json = fresh_dir(peer + "_fixture") + ".json";
    const Outcome r = run("certify " + fixtures + peer + "-constant-20deg.msh --field constant " + rotated_metric(20) + " --json " + json);
    ASSERT_LE(r.exit_code, 1) << r.err;  // bamg's is locally uniform here (Delaunay in a constant metric)
    const Json c = read_json(json);
    EXPECT_TRUE(c["valid"]["holds"].get<bool>());
    if (peer == "gmsh") {
      EXPECT_LT(unit_share(c), 0.7);
      EXPECT_LT(median_quality(c), 0.5);
      EXPECT_GT(c["vertices"].get<double>(), 3 * 1155.0);
    } else {
      EXPECT_GE(unit_share(c), 0.9);
      EXPECT_GE(median_quality(c), 0.9);
      EXPECT_LT(c["vertices"].get<double>(), 2 * 1155.0);
    }
    fs::remove(json);
  }
}

// `anisocert dual` on peers' meshes: a report whose counts add up, and a verdict. Which triangles
// are dual is checked against CGAL (tests/cgal, DualVsCgal); a peer mesh is not the dual of its
// own diagram (Gmsh and FreeFem are Delaunay in no metric of LS's kind), and the report says so.
TEST(PeerDual, ReportsEveryTriangleOfAPeerMesh) {
  for (const std::string peer : {"gmsh", "freefem"}) {
    SCOPED_TRACE(peer);
    const std::string json = fresh_dir(peer + "_dual") + ".json";
    const Outcome r = run("dual --quiet " + fixtures + peer + "-lshape-shock-coarse.msh --field shock --param h=0.1 --json " + json);
    ASSERT_EQ(r.exit_code, 1) << r.err;
    const Json d = read_json(json);
    const auto& t = d["triangles"];
    EXPECT_EQ(t["dual"].get<std::size_t>() + t["ties"].get<std::size_t>() + t["not_dual"].get<std::size_t>(),
              d["input"]["triangles"].get<std::size_t>());
    EXPECT_GT(t["dual"].get<std::size_t>(), 0u);
    EXPECT_GT(t["not_dual"].get<std::size_t>() + d["missing"]["count"].get<std::size_t>(), 0u);
    EXPECT_EQ(d["input"]["domain_corners"].get<int>(), 6);  // the L-shape's corners: straight runs merged
    fs::remove(json);
  }
}

// FreeFem++'s own metric as the LS refiner's background field (issue 16's inputs: every field,
// background meshes included), an input no anisocert code made: adaptmesh three times to the layer
// tanh(20(x + y − 1)), then the Hessian metric it adapted to, written as BAMG's .mtr ("nbv 3",
// a11 a21 a22) beside FreeFem's .msh (as a new user made it, docs/refiners.md). The metric is
// strongly anisotropic (eigenvalue ratio above 100 at some vertex, computed here from the file), so
// the run takes the path of sites with different metrics. The run ends with no violator (exit 0),
// and `anisocert dual`, reading the Medit files back, certifies the mesh the exact dual of its
// vertices' diagram, with no orphan (exit 0: LS §7). The BWY refiner (issue 17) on the same field
// ends with no rule applying, and `dual` certifies its T the exact dual too.
TEST(PeerMetric, LsAndBwyRefineFreeFemsHessianMetricAndTheOracleCertifiesThem) {
  const std::string d = fresh_dir("freefem_metric");
  fs::create_directories(d);
  std::ofstream(d + "/metric.edp") << "mesh Th = square(10, 10);\n"
                                      "fespace Vh(Th, P1);\n"
                                      "Vh u = tanh(20*(x + y - 1));\n"
                                      "for (int i = 0; i < 3; i++) {\n"
                                      "  Th = adaptmesh(Th, u, err = 0.02, hmin = 0.005);\n"
                                      "  u = tanh(20*(x + y - 1));\n"
                                      "}\n"
                                      "fespace Mh(Th, P1);\n"
                                      "Mh m11, m21, m22;\n"
                                      "Th = adaptmesh(Th, u, err = 0.02, hmin = 0.005, metric = [m11[], m21[], m22[]], nomeshgeneration = true);\n"
                                      "savemesh(Th, \"" + d + "/bg.msh\");\n"
                                      "ofstream f(\"" + d + "/bg.mtr\");\n"
                                      "f.precision(17);\n"
                                      "f << Th.nv << \" 3\\n\";\n"
                                      "for (int i = 0; i < Th.nv; i++) f << m11[][i] << \" \" << m21[][i] << \" \" << m22[][i] << \"\\n\";\n";
  const Outcome ff = run_command("FreeFem++ -nw -ne -v 0 " + d + "/metric.edp");
  ASSERT_EQ(ff.exit_code, 0) << ff.out << ff.err;
  std::ifstream mtr(d + "/bg.mtr");
  std::size_t nbv = 0, kind = 0;
  mtr >> nbv >> kind;
  ASSERT_EQ(kind, 3u);
  double ratio = 1;
  for (double a, b, c; mtr >> a >> b >> c;) {
    const double mean = (a + c) / 2, radius = std::hypot((a - c) / 2, b);
    ratio = std::max(ratio, (mean + radius) / (mean - radius));
  }
  EXPECT_GT(ratio, 100) << "FreeFem's metric is nearly isotropic: the test no longer exercises anisotropy";
  // Each refiner: its stop when no rule applies, and what `dual` must say of its mesh.
  for (const auto& [algo, stop, certified] :
       {std::tuple{"ls", "stopped: no encroached subsegment and no violator", " 0 orphans"},
        std::tuple{"bwy", "stopped: no rule of BWY §3.2.2 applies", "the mesh is the dual of the anisotropic Voronoi diagram of its vertices"}}) {
    const std::string mesh = d + "/" + algo + ".mesh";
    const Outcome r = run(std::string("refine --algo ") + algo + " --field background:" + d + "/bg.msh:" + d + "/bg.mtr --size 0.5 --quiet -o " + mesh);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find(stop), std::string::npos) << r.out;
    const Outcome dual = run("dual " + mesh + " --quiet");
    EXPECT_EQ(dual.exit_code, 0) << dual.out << dual.err;
    EXPECT_NE(dual.out.find(certified), std::string::npos) << dual.out;
  }
  fs::remove_all(d);
}

// --- bad input: which peer, which step, why; exit 2 and nothing written ------------------------

// A stand-in peer program: a shell script in a fresh folder.
std::string fake_peer(const std::string& name, const std::string& body) {
  const std::string dir = fresh_dir("fake_" + name);
  fs::create_directories(dir);
  const std::string path = dir + "/" + name;
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

void expect_refused(const Outcome& r, const std::string& message, const std::string& out) {
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out + "/mesh.msh"));
  EXPECT_FALSE(fs::exists(out + "/certify.json"));
}

TEST(ValidateBadInput, MissingPeer) {
  const std::string out = fresh_dir("missing");
  expect_refused(validate("--peer gmsh --out " + out, "GMSH=/nonexistent/gmsh"), "validate: gmsh: /nonexistent/gmsh is not installed", out);
}

TEST(ValidateBadInput, PeerFails) {
  const std::string out = fresh_dir("fails");
  const std::string gmsh = fake_peer("gmsh", "echo 'Error   : no license for BAMG' >&2; exit 1");
  expect_refused(validate("--peer gmsh --out " + out, "GMSH=" + gmsh),
                 "validate: gmsh: meshing (gmsh): exit 1: Error   : no license for BAMG", out);
}

TEST(ValidateBadInput, PeerRunsOverItsTime) {
  const std::string out = fresh_dir("slow");
  const std::string freefem = fake_peer("FreeFem++", "sleep 30");
  expect_refused(validate("--peer freefem --timeout 1 --out " + out, "FREEFEM=" + freefem),
                 "validate: freefem: initial mesh (FreeFem++): stopped after 1 s (--timeout)", out);
}

TEST(ValidateBadInput, PeerWritesAMalformedMesh) {
  const std::string out = fresh_dir("malformed");
  // Writes "$MeshFormat" and nothing else where -o says.
  const std::string gmsh = fake_peer("gmsh", "while [ $# -gt 0 ]; do [ \"$1\" = -o ] && printf '$MeshFormat\\n' > \"$2\"; shift; done");
  expect_refused(validate("--peer gmsh --out " + out, "GMSH=" + gmsh), "validate: gmsh: its mesh: anisocert: mesh.msh", out);
}

TEST(ValidateBadInput, AnOptionWithoutItsValueIsRefusedNotLoopedOn) {
  const Outcome r = run_command("timeout 20 bash " + source_dir + "/scripts/validate --peer gmsh --field");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "validate: --field needs a value (see scripts/validate --help)\n");
}

TEST(ValidateBadInput, AnOutThatIsAFileIsRefusedBeforeAnyWork) {
  const std::string file = fresh_dir("out_file");
  std::ofstream(file) << "not a folder\n";
  const Outcome r = validate("--peer bamg --out " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");  // refused before the peer ran
  EXPECT_EQ(r.err, "validate: --out: cannot write in \"" + file + "\"\n");
  fs::remove(file);
}

// The steps run in a temporary folder: a relative --out is where the user is, not there.
TEST(Validate, ARelativeOutIsWrittenWhereTheUserIs) {
  const std::string cwd = fresh_dir("relative");
  fs::create_directories(cwd);
  const Outcome r = run_command("cd " + cwd + " && ANISOCERT=" + std::string(ANISOCERT_BIN) + " bash " + source_dir +
                                "/scripts/validate --peer bamg --rounds 1 --out here");
  EXPECT_LE(r.exit_code, 1) << r.err;
  for (const char* f : {"mesh.msh", "certify.json", "certify.svg", "certify.txt"}) EXPECT_TRUE(fs::exists(cwd + "/here/" + f)) << f;
  fs::remove_all(cwd);
}

TEST(ValidateBadInput, BadFieldParameterNamesTheStep) {
  const std::string out = fresh_dir("param");
  expect_refused(validate("--peer bamg --param h=-1 --out " + out),
                 "validate: bamg: round 1: metric at the vertices (anisocert metric): exit 2: anisocert: --field:", out);
}

}  // namespace
