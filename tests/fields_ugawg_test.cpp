// The 3D fields (fields/ugawg.cpp, fields/constant.cpp) against the UGAWG benchmark's README
// formulas evaluated by hand at chosen points (github.com/UGAWG/adapt-benchmarks, cube/ and
// cube-cylinder/), h0 = 10⁻³ unless said:
//  - linear: h_z = h0 + 2(0.1 − h0)|z − 0.5| is h0 at z = 0.5 and 0.1 at z = 0 and 1;
//  - polar-1 at (0.5, 0, z): r = 0.5, h_r = h0, the radial direction x: M = diag(10⁶, 100, 100);
//    at (0, 0.75, z): h_r = h0 + 0.198·0.25 = 0.0505, radial y: M = diag(100, 0.0505⁻², 100);
//  - polar-2 at (0.55, 0, z): d = 0.5, h_t = 0.5/40 + 0.5·0.1 = 0.0625: M22 = 256; at r = 0.4,
//    d = 2 and h_t = 0.05 − 0.1 < 0: no metric (outside the cube-cylinder domain, r >= 0.5);
//  - constant: the identity by default; diag(−1, −1, 1) (det +1, not positive definite) refused.
#include "fields/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using anisocert::fields::make_field3;

void expect_near(double got, double want) { EXPECT_NEAR(got, want, 1e-9 * std::abs(want)) << "want " << want; }

TEST(UgawgFields, LinearHasItsLayerAtZOneHalf) {
  const auto f = make_field3("ugawg-linear", {});
  for (double z : {0.0, 1.0}) {
    const auto M = f.at(0.3, 0.7, z);
    expect_near(M.m11, 100);
    expect_near(M.m22, 100);
    expect_near(M.m33, 100);
    EXPECT_EQ(M.m12, 0);
    EXPECT_EQ(M.m13, 0);
    EXPECT_EQ(M.m23, 0);
  }
  expect_near(f.at(0.3, 0.7, 0.5).m33, 1e6);
  expect_near(make_field3("ugawg-linear", {{"h0", 0.01}}).at(0, 0, 0.5).m33, 1e4);
  EXPECT_THROW(make_field3("ugawg-linear", {{"h0", 0}}), std::invalid_argument);
}

TEST(UgawgFields, PolarOneIsFineAcrossTheCylinderR05) {
  const auto f = make_field3("ugawg-polar1", {});
  const auto a = f.at(0.5, 0, 0.2);
  expect_near(a.m11, 1e6);
  expect_near(a.m22, 100);
  expect_near(a.m33, 100);
  EXPECT_NEAR(a.m12, 0, 1e-6);
  const auto b = f.at(0, 0.75, 0.9);
  expect_near(b.m11, 100);
  expect_near(b.m22, 1 / (0.0505 * 0.0505));
  expect_near(b.m33, 100);
  // At 45°, the radial and θ directions mix: m12 = (1/h_r² − 1/h_t²)/2.
  const double r = 0.75, c = std::sqrt(0.5);
  const auto d = f.at(r * c, r * c, 0);
  expect_near(d.m12, (1 / (0.0505 * 0.0505) - 100) / 2);
  expect_near(d.m11, (1 / (0.0505 * 0.0505) + 100) / 2);
}

TEST(UgawgFields, PolarTwoRefinesThetaNearTheLayerAndHasNoMetricInsideTheCylinder) {
  const auto f = make_field3("ugawg-polar2", {});
  expect_near(f.at(0.55, 0, 0).m22, 256);
  expect_near(f.at(0.7, 0, 0).m22, 100);  // d < 0: h_t = 0.1
  EXPECT_THROW(f.at(0.4, 0, 0), anisocert::fields::FieldError);
}

TEST(UgawgFields, ConstantIn3DMustBePositiveDefinite) {
  const auto M = make_field3("constant", {}).at(1, 2, 3);
  EXPECT_EQ(M.m11, 1);
  EXPECT_EQ(M.m22, 1);
  EXPECT_EQ(M.m33, 1);
  EXPECT_EQ(M.m12, 0);
  EXPECT_THROW(make_field3("constant", {{"m11", -1}, {"m22", -1}}), std::invalid_argument);
  try {
    make_field3("linear", {});
    ADD_FAILURE() << "a 2D field made in 3D";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown 3D field \"linear\" (constant, ugawg-linear, ugawg-polar1, ugawg-polar2)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace

// The constant fields refuse a metric that is not positive definite, at the boundary too: a
// singular [1 1; 1 1] (det 0, campaign mutant 179 accepted it) and its 3D twin, diag(1, 1, 0).
TEST(ConstantFields, SingularMetricsAreRefused) {
  EXPECT_THROW(anisocert::fields::make_field("constant", {{"m11", 1}, {"m12", 1}, {"m22", 1}}), std::invalid_argument);
  EXPECT_NO_THROW(anisocert::fields::make_field("constant", {{"m11", 1}, {"m12", 0.5}, {"m22", 1}}));
  EXPECT_THROW(make_field3("constant", {{"m33", 0}}), std::invalid_argument);
  EXPECT_THROW(make_field3("constant", {{"m12", 1}}), std::invalid_argument);  // [1 1 0; 1 1 0; 0 0 1]: minor 0
  EXPECT_NO_THROW(make_field3("constant", {{"m12", 0.5}}));
}

// The 2D fields' parameters in their ranges: alpha of shock and radial may be 0 (no stretch), not
// negative (campaign mutant 183 let a negative alpha through: a shrink the fields do not define,
// and below −1 a metric that is not positive definite across the layer).
TEST(FieldParameters, ANegativeStretchIsRefusedByName) {
  for (const char* field : {"shock", "radial"}) {
    EXPECT_NO_THROW(anisocert::fields::make_field(field, {{"alpha", 0}})) << field;
    try {
      anisocert::fields::make_field(field, {{"alpha", -0.5}});
      ADD_FAILURE() << field << ": a negative alpha was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), std::string("parameter alpha of field ") + field + " must be >= 0");
    }
  }
}
