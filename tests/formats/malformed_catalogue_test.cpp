// The catalogue of malformed mesh and metric files (tests/formats/malformed/<what-is-wrong>/): each
// is certified as a user would, `anisocert certify MESH [--metric METRIC] [ARGS] --json OUT --svg
// OUT`, and must give exit 2, one line on standard error naming the file and containing the
// case's message, and no output file (DESIGN.md § Command line: bad input writes nothing).
// case.json: {"mesh": FILE, "metric": FILE (optional), "args": [..] (optional), "message": TEXT}.
#include "../cli_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace {

namespace fs = std::filesystem;

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& d : fs::directory_iterator(ANISOCERT_MALFORMED_DIR))
    if (fs::exists(d.path() / "case.json")) names.push_back(d.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Malformed : public ::testing::TestWithParam<std::string> {};

TEST_P(Malformed, ExitTwoWithTheFileAndTheProblemNamedAndNothingWritten) {
  const fs::path dir = fs::path(ANISOCERT_MALFORMED_DIR) / GetParam();
  std::ifstream in(dir / "case.json");
  const nlohmann::json c = nlohmann::json::parse(in);
  for (const auto& [key, value] : c.items())
    ASSERT_TRUE(key == "mesh" || key == "metric" || key == "args" || key == "message") << "unknown key " << key;
  const fs::path out = fs::path(::testing::TempDir()) / ("malformed_" + GetParam());
  fs::remove_all(out);
  fs::create_directories(out);
  const std::string mesh = (dir / c["mesh"].get<std::string>()).string();
  std::string args = "certify '" + mesh + "'";
  if (c.contains("metric")) args += " --metric '" + (dir / c["metric"].get<std::string>()).string() + "'";
  for (const auto& a : c.value("args", nlohmann::json::array())) args += " " + a.get<std::string>();
  args += " --json '" + (out / "report.json").string() + "' --svg '" + (out / "report.svg").string() + "'";
  const Outcome r = run(args);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(c["message"].get<std::string>()), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr: " << r.err;
  const std::string named = c.contains("metric") && r.err.find(c["metric"].get<std::string>()) != std::string::npos
                                ? c["metric"].get<std::string>()
                                : c["mesh"].get<std::string>();
  EXPECT_NE(r.err.find(named), std::string::npos) << "the message names no file: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(fs::is_empty(out)) << "an output was written";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, Malformed, ::testing::ValuesIn(case_names()),
                         [](const auto& info) {
                           std::string n = info.param;
                           std::replace_if(n.begin(), n.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
                           return n;
                         });

}  // namespace
