// Regressions as data (the way artem-ogre/CDT keeps its inputs): each folder of tests/regressions/
// is named after what it caught and holds its inputs and case.json, which says what went wrong,
// what found it, what to run and what must come out (with the reason it must). One table-driven
// test runs every folder; a new regression is a new folder.
//   "run": "diagram"  the exact diagram of "input": counts, flags, nodes located at exact points,
//                     brute-force agreement on a grid;
//          "refine"   a refiner of the registry on "domain" and a built-in field, once per entry of
//                     "params": consistency, and the exact certifier's verdict at the run's ρ₀, γ₀;
//          "cli"      `anisocert ARGS` ({case}: the folder, {tmp}: a fresh temporary folder): the
//                     exit code, fragments of standard output and error, the number of lines on
//                     standard error, files that must not exist; then the commands of "then", each
//                     with its own args and expect, in the same folder;
//          "conics"   the exact common points of two conics and the signs of polynomials there.
#include "fields/registry.hpp"
#include "io/mesh_json.hpp"
#include "oracle/algebraic/conic_intersection.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/diagram/diagram.hpp"
#include "predicates/orientation.hpp"
#include "refiners/registry.hpp"
#include "tests/brute_force.hpp"
#include "tests/cli_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>

namespace {

namespace fs = std::filesystem;
using namespace anisocert;
using Json = nlohmann::json;

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(ANISOCERT_REGRESSIONS_DIR))
    if (entry.is_directory()) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

Json read_json(const fs::path& p) {
  std::ifstream in(p);
  return Json::parse(in);
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

void run_diagram(const fs::path& dir, const Json& c) {
  const geometry::Mesh<Rational> in = io::read_mesh_json_file((dir / c.at("input").get<std::string>()).string());
  const oracle::Diagram d = oracle::compute_diagram(in);
  const Json& e = c.at("expect");
  if (e.contains("faces")) {
    EXPECT_EQ(d.faces.size(), e["faces"].get<std::size_t>());
  }
  if (e.contains("orphans")) {
    EXPECT_EQ(std::count_if(d.faces.begin(), d.faces.end(), [](const oracle::Face& f) { return f.orphan; }), e["orphans"].get<long>());
  }
  if (e.contains("theorem7_preconditions")) {
    EXPECT_EQ(d.theorem7.preconditions_hold, e["theorem7_preconditions"].get<bool>());
  }
  if (e.contains("dual_is_triangulation")) {
    EXPECT_EQ(d.dual_check.is_triangulation, e["dual_is_triangulation"].get<bool>());
  }
  for (const Json& n : e.value("nodes", Json::array())) {
    const predicates::Point2<Rational> at{parse_rational(n["at"][0].get<std::string>()), parse_rational(n["at"][1].get<std::string>())};
    const oracle::Location loc = oracle::locate(d, at);
    EXPECT_EQ(loc.kind, oracle::Location::Kind::node) << "at " << n["at"];
    EXPECT_EQ(loc.owners, n["owners"].get<std::vector<int>>()) << "at " << n["at"];
  }
  if (e.contains("brute_force_grid")) test_support::expect_brute_force_agrees(d, e["brute_force_grid"].get<int>());
}

void run_refine(const fs::path& dir, const Json& c) {
  const io::DomainFile input = io::read_domain_file((dir / c.at("domain").get<std::string>()).string());
  const geometry::Polygon<Rational>& corners = input.corners;
  for (int k : c.value("reflex_corners", std::vector<int>{})) {  // the data still exercises what it caught
    const std::size_t m = corners.size();
    ASSERT_EQ(predicates::orientation(corners[(k + m - 1) % m], corners[k], corners[(k + 1) % m]), Sign::negative)
        << "corner " << k << " is not reflex";
  }
  const refiners::RefinerEntry* entry = refiners::find_refiner(c.at("algo").get<std::string>());
  ASSERT_NE(entry, nullptr);
  const refiners::ParameterValues values = entry->defaults();
  refiners::common::Budget budget;
  budget.max_vertices = c.value("max_vertices", budget.max_vertices);
  const Json& e = c.at("expect");
  for (const Json& params : c.at("params")) {
    SCOPED_TRACE("field parameters " + params.dump());
    const fields::MetricField field = fields::make_field(c.at("field").get<std::string>(), params.get<fields::Parameters>());
    const refiners::Run run =
        entry->run(refiners::common::Domain::from_exact(corners, input.points, input.interior_segments), field, values, budget, 1, {});
    EXPECT_EQ(run.result.consistent, e.at("consistent").get<bool>()) << run.result.stop_reason;
    if (e.contains("certified")) {
      oracle::CertifyOptions o;
      o.rho0 = rational_from_double(values.at("rho0")), o.gamma0 = rational_from_double(values.at("gamma0"));
      EXPECT_EQ(oracle::certify_mesh(geometry::exact(run.result.mesh), o).holds(o), e["certified"].get<bool>());
    }
  }
}

// One command of a "cli" case and what must come out of it.
void run_command(const Json& command, const std::function<std::string(const std::string&)>& expand) {
  std::string args;
  for (const Json& a : command.at("args")) args += " '" + expand(a.get<std::string>()) + "'";
  const Outcome r = run(args);
  const Json& e = command.at("expect");
  EXPECT_EQ(r.exit_code, e.at("exit").get<int>()) << args << "\n" << r.err;
  if (e.contains("stdout_contains")) {
    EXPECT_NE(r.out.find(e["stdout_contains"].get<std::string>()), std::string::npos) << r.out;
  }
  if (e.contains("stderr_contains")) {
    EXPECT_NE(r.err.find(e["stderr_contains"].get<std::string>()), std::string::npos) << r.err;
  }
  if (e.contains("stderr_lines")) {  // the contract for bad input: one line
    EXPECT_EQ(static_cast<std::size_t>(std::count(r.err.begin(), r.err.end(), '\n')), e["stderr_lines"].get<std::size_t>()) << r.err;
  }
  for (const Json& f : e.value("absent", Json::array())) {
    EXPECT_FALSE(fs::exists(expand(f.get<std::string>()))) << f;
  }
}

// The case's command, then those of "then" (each with its own "args" and "expect"), in one
// temporary folder: a later command may check what an earlier one wrote.
void run_cli(const fs::path& dir, const Json& c) {
  const fs::path tmp = fs::path(::testing::TempDir()) / ("anisocert_regression_" + std::to_string(getpid()));
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  auto expand = [&](const std::string& s) { return replace_all(replace_all(s, "{case}", dir.string()), "{tmp}", tmp.string()); };
  run_command(c, expand);
  for (const Json& next : c.value("then", Json::array())) run_command(next, expand);
  fs::remove_all(tmp);
}

oracle::Conic conic(const Json& j) {
  std::array<Rational, 6> q;
  for (int i = 0; i < 6; ++i) q[i] = j[i].get<long>();
  return {q[0], q[1], q[2], q[3], q[4], q[5]};
}

void run_conics(const Json& c) {
  const oracle::ConicIntersection r = oracle::intersect(conic(c.at("conics")[0]), conic(c.at("conics")[1]));
  const Json& e = c.at("expect");
  ASSERT_EQ(r.points.size(), e.at("points").get<std::size_t>());
  for (const Json& s : e.value("signs", Json::array())) {
    oracle::Bivariate p;
    for (const Json& t : s.at("polynomial")) p.add(t[0].get<int>(), t[1].get<int>(), t[2].get<long>());
    for (std::size_t i = 0; i < r.points.size(); ++i)
      EXPECT_EQ(static_cast<int>(r.points[i].point.sign_of(p)), s.at("at_points")[i].get<int>())
          << "polynomial " << s["polynomial"] << " at point " << i;
  }
}

// Every key of j is one of `allowed`: a misspelt expectation would otherwise never be checked.
void expect_only_keys(const Json& j, std::initializer_list<const char*> allowed, const std::string& where) {
  for (const auto& item : j.items())
    EXPECT_NE(std::find_if(allowed.begin(), allowed.end(), [&](const char* k) { return item.key() == k; }), allowed.end())
        << where << ": unknown key \"" << item.key() << "\"";
}

void expect_cli_keys(const Json& command) {
  expect_only_keys(command.at("expect"), {"why", "exit", "stdout_contains", "stderr_contains", "stderr_lines", "absent"}, "expect");
}

class Regression : public ::testing::TestWithParam<std::string> {};

TEST_P(Regression, StillAnsweredRight) {
  const fs::path dir = fs::path(ANISOCERT_REGRESSIONS_DIR) / GetParam();
  const Json c = read_json(dir / "case.json");
  RecordProperty("caught", c.at("caught").get<std::string>());
  SCOPED_TRACE(c.at("caught").get<std::string>() + " — " + c.at("expect").value("why", ""));
  const std::string kind = c.at("run").get<std::string>();
  if (kind == "diagram") {
    expect_only_keys(c, {"caught", "found_by", "run", "input", "expect"}, "case.json");
    expect_only_keys(c.at("expect"), {"why", "faces", "orphans", "theorem7_preconditions", "dual_is_triangulation", "nodes",
                                      "brute_force_grid"},
                     "expect");
  } else if (kind == "refine") {
    expect_only_keys(c, {"caught", "found_by", "run", "algo", "domain", "reflex_corners", "field", "params", "max_vertices", "expect"},
                     "case.json");
    expect_only_keys(c.at("expect"), {"why", "consistent", "certified"}, "expect");
  } else if (kind == "cli") {
    expect_only_keys(c, {"caught", "found_by", "run", "args", "expect", "then"}, "case.json");
    expect_cli_keys(c);
    for (const Json& command : c.value("then", Json::array())) {
      expect_only_keys(command, {"args", "expect"}, "then");
      expect_cli_keys(command);
    }
  } else if (kind == "conics") {
    expect_only_keys(c, {"caught", "found_by", "run", "conics", "expect"}, "case.json");
    expect_only_keys(c.at("expect"), {"why", "points", "signs"}, "expect");
  }
  if (kind == "diagram") run_diagram(dir, c);
  else if (kind == "refine") run_refine(dir, c);
  else if (kind == "cli") run_cli(dir, c);
  else if (kind == "conics") run_conics(c);
  else FAIL() << "unknown run \"" << kind << "\"";
}

INSTANTIATE_TEST_SUITE_P(Data, Regression, ::testing::ValuesIn(case_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
