// BWY at small input angles (refiners/common/corner_shells.hpp): the square under the constant
// metric diag(100, 10⁴) rotated 20° (tests/peers/fixtures/README.md), whose corners 1 and 3 are 18°
// in the metric, and a triangle with a 14° corner. BWY split the edges at those corners in turn,
// each split made instead of inserting the circumcentre of the skinny triangle there, down to 2⁻³⁰
// of the edge. With the shells and the exemption the runs finish, the oracle certifies them, and
// the Voronoi vertices left badly shaped (radius-edge ratio above B in the metric, computed here
// in doubles) are across the sharp corners, as many as the run reports.
#include "fields/registry.hpp"
#include "geometry/mesh.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "refiners/bwy/bwy_refiner.hpp"
#include "refiners/bwy/rules.hpp"
#include "tests/small_angle_triangles.hpp"

#include <gtest/gtest.h>

namespace {

using namespace anisocert;
using predicates::Point2;
using predicates::Sym2;

struct Case {
  std::vector<Point2<double>> corners;
  Sym2<double> M;
  std::vector<int> sharp;
};

TEST(BwyRefiner, SharpCornersGetShellsAndTheirBadlyShapedTrianglesAreTheExemptOnes) {
  const Sym2<double> rotated{1258.0800065610586, -3181.7986679483697, 8841.9199934389417};
  for (const Case& c : {Case{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, rotated, {1, 3}}, Case{{{0, 0}, {1, 0}, {0.96875, 0.25}}, {400, 0, 400}, {0}}}) {
    refiners::bwy::BwyParameters p;
    const auto r = refiners::bwy::refine_bwy(refiners::common::Domain(c.corners),
                                             fields::make_field("constant", {{"m11", c.M.m11}, {"m12", c.M.m12}, {"m22", c.M.m22}}), p);
    ASSERT_TRUE(r.consistent) << r.stop_reason;
    const oracle::Diagram d = oracle::compute_diagram(geometry::exact(r.mesh));
    EXPECT_TRUE(d.dual_check.is_triangulation);
    EXPECT_TRUE(oracle::compare_with_dual(d, r.mesh.triangles, 3).is_dual());
    // Each sharp corner's lopping: a site on each of its edges before any other split.
    ASSERT_GE(r.trace.size(), 2 * c.sharp.size());
    for (std::size_t k = 0; k < 2 * c.sharp.size(); ++k) EXPECT_EQ(r.trace[k].rule, refiners::bwy::number(refiners::bwy::Rule::corner_shell));
    const std::size_t skinny = test_support::skinny_across_corners(r.mesh, c.corners, c.sharp, c.M,
                                                              [&](const test_support::MetricTriangle& t) { return t.radius_edge() <= p.shape_bound; });
    EXPECT_GT(skinny, 0u);
    EXPECT_EQ(r.exempt_left, skinny);
  }
}

}  // namespace
