// The `anisocert theory` commands as a user runs them: JSON contract, exit codes, messages.

#include "numbers/rational.hpp"
#include "tests/cli_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace {

using Json = nlohmann::ordered_json;

void expect_enclosure(const Json& j, const std::string& key) {
  ASSERT_TRUE(j.contains(key)) << key;
  ASSERT_EQ(j[key].size(), 2u) << key;
  const anisocert::Rational lo = anisocert::parse_rational(j[key]["lo"].get<std::string>());
  const anisocert::Rational hi = anisocert::parse_rational(j[key]["hi"].get<std::string>());
  EXPECT_LE(lo, hi) << key;
}

void expect_bad_input(const std::string& args, const std::string& mentions) {
  Outcome r = run(args);
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_TRUE(r.out.empty()) << args << ": no partial output";
  EXPECT_NE(r.err.find(mentions), std::string::npos) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

}  // namespace

TEST(Cli, TheoryJsonHasTheContractKeysForTheFiveDefaultAngles) {
  Outcome r = run("theory --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json rows = Json::parse(r.out);
  ASSERT_TRUE(rows.is_array());
  ASSERT_EQ(rows.size(), 5u);
  const char* thetas[] = {"0", "5", "10", "15", "20"};
  for (size_t k = 0; k < 5; ++k) {
    const Json& row = rows[k];
    EXPECT_EQ(row["theta_deg"], thetas[k]);
    auto it = row.begin();
    for (const char* key : {"theta_deg", "gamma", "segment_angle_deg", "distance_factor", "theta_max_deg"})
      EXPECT_EQ((it++).key(), key);  // the contract's keys first, in order
    for (const char* key : {"gamma", "segment_angle_deg", "distance_factor", "theta_max_deg", "LS_L5_factor",
                            "LS_L14_factor", "LS_L18_factor", "LS_L21_site_factor", "LS_L21_bdr_factor",
                            "LS_L23_factor"})
      expect_enclosure(row, key);
  }
}

TEST(Cli, OneThetaGivesOneObjectParsedExactly) {
  Outcome r = run("theory --theta 12.5 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json j = Json::parse(r.out);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j["theta_deg"], "12.5");
  Outcome f = run("theory --theta 25/2 --json");
  EXPECT_EQ(f.out, r.out);  // the same rational, whatever its spelling
  Outcome two = run("theory --theta 1/3 --theta 20.7 --json");
  ASSERT_EQ(two.exit_code, 0);
  EXPECT_EQ(Json::parse(two.out).size(), 2u);
  EXPECT_EQ(Json::parse(two.out)[0]["theta_deg"], "1/3");
}

TEST(Cli, ThetaWithinTenToMinusHundredOfThetaMax) {
  // Review finding: the printed bracket was re-checked at the default precision although γ
  // needed more there; P(1) ≈ −5·10⁻¹⁰² at this θ.
  Json j = Json::parse(run("theory --theta 0 --json --digits 130").out);
  std::string theta_max = j["theta_max_deg"]["lo"].get<std::string>();
  std::string theta = theta_max.substr(0, theta_max.find('.') + 101);  // truncated: below θ_max
  Outcome r = run("theory --json --theta " + theta);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Json::parse(r.out)["theta_deg"], theta);
  EXPECT_EQ(run("theory --theta " + theta_max.substr(0, theta_max.find('.') + 100) + "9").exit_code, 2);
}

TEST(Cli, TableIsReadable) {
  Outcome r = run("theory");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("1.12783848556168226026"), std::string::npos);  // γ(0), φ^(1/4)
  EXPECT_NE(r.out.find("20.7048110546354296692"), std::string::npos);  // θ_max
}

TEST(Cli, BadArgumentsGiveOneLineAndExitTwo) {
  expect_bad_input("theory --theta 25", "--theta 25");
  expect_bad_input("theory --theta 20.705", "out of range");
  expect_bad_input("theory --theta -1", "out of range");
  expect_bad_input("theory --theta abc", "\"abc\"");
  expect_bad_input("theory --theta 1/0", "zero denominator");
  expect_bad_input("theory --digits 3", "--digits");
  expect_bad_input("theory --frobnicate", "frobnicate");
  expect_bad_input("frobnicate", "frobnicate");
  expect_bad_input("", "subcommand");
  expect_bad_input("theory chi --beta 0 --gamma 1", "--beta");
  expect_bad_input("theory bwy --B 1", "--B");
  expect_bad_input("theory bwy --B 2 --G 0.5", "--G");
  expect_bad_input("theory lu --rho0 3 --gamma0 1 --delta 0.1 --beta 3", "gamma0");
  expect_bad_input("theory --theta 5 chi --beta 1 --gamma 1", "--theta");
}

TEST(Cli, HelpEverywhere) {
  for (const char* args : {"--help", "theory --help", "theory chi --help", "theory bwy --help", "theory lu --help"}) {
    Outcome r = run(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << args;
  }
  EXPECT_NE(run("theory --help").out.find("--theta"), std::string::npos);
  EXPECT_NE(run("theory lu --help").out.find("--gamma0"), std::string::npos);
}

TEST(Cli, ConicsJsonContract) {
  // x² + 4y² = 4 and x² − y² = 1: (±√(8/5), ±√(3/5)); √1.6 = 1.2649110640673517327995574177731…
  Outcome r = run("conics 1 0 4 0 0 -4 1 0 -1 0 0 -1 --json --digits 12");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Json j = Json::parse(r.out);
  EXPECT_EQ(j["shared_component"], false);
  ASSERT_EQ(j["points"].size(), 4u);
  EXPECT_EQ(j["points"][0]["x"], "-1.26491106407");
  EXPECT_EQ(j["points"][0]["y"], "-0.774596669241");
  EXPECT_EQ(j["points"][0]["multiplicity"], 1);
  auto it = j.begin();
  EXPECT_EQ((it++).key(), "shared_component");
  EXPECT_EQ(it.key(), "points");
  // Identical conics (as fractions and decimals): a shared component, no points.
  Json s = Json::parse(run("conics 1 0 1 0 0 -1 0.5 0 1/2 0 0 -0.5 --json").out);
  EXPECT_EQ(s["shared_component"], true);
  EXPECT_TRUE(s["points"].empty());
  expect_bad_input("conics 1 0 1 0 0 -1 1 0 1", "12 coefficients");
  expect_bad_input("conics 1 0 1 0 0 x 1 0 1 0 0 1", "A6");
  expect_bad_input("conics 0 0 0 0 0 0 1 0 1 0 0 -1", "whole plane");
}

TEST(Cli, VerdictsExitZeroOrOne) {
  Outcome holds = run("theory chi --beta 1 --gamma 1 --json");
  ASSERT_EQ(holds.exit_code, 0);
  Json j = Json::parse(holds.out);
  EXPECT_EQ(j["chi"], "0.5");
  expect_enclosure(j, "LS_T9_min_angle_deg");
  EXPECT_EQ(run("theory chi --beta 4/3 --gamma 5/4").exit_code, 1);  // χ = 0 exactly

  Outcome bwy = run("theory bwy --B 1.5 --G 1.1 --json");
  ASSERT_EQ(bwy.exit_code, 1);
  Json b = Json::parse(bwy.out);
  EXPECT_EQ(b["holds"], false);
  EXPECT_EQ(b["failing"][0], "lemma2");
  EXPECT_EQ(run("theory bwy --B 1.5 --G 1.0009").exit_code, 0);
  EXPECT_EQ(run("theory bwy --B 2").exit_code, 0);

  EXPECT_EQ(run("theory lu --rho0 4 --gamma0 1.1 --delta 0.1 --beta 4").exit_code, 0);
  Outcome lu = run("theory lu --rho0 3 --gamma0 1.1 --delta 0.1 --beta 3 --json");
  ASSERT_EQ(lu.exit_code, 1);
  EXPECT_EQ(Json::parse(lu.out)["failing"], Json::array({"lemma43", "lemma44"}));
}
