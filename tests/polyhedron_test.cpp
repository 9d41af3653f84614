// Polyhedral domains (geometry/polyhedron.hpp, issue 40): the outward boundary of a solid passes;
// each defect is made on purpose and named (open, not a 2-manifold at an edge or a vertex,
// inconsistently oriented, inward, crossing itself). Surfaces: the boundary of Kuhn-grid cubes
// (many coplanar facets sharing a vertex or an edge, which must not count as meeting), an L-shaped
// (non-convex) one, and a twisted prism.
#include "geometry/kuhn_grid.hpp"
#include "geometry/polyhedron.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace {

using anisocert::Rational;
using anisocert::geometry::Polyhedron;
using anisocert::geometry::polyhedron_defect;

// The outward boundary of the tetrahedra of the n³ Kuhn grid (positively oriented) whose cube
// (x, y, z) `keep` accepts: the faces in one kept tetrahedron, outward.
template <class Keep>
Polyhedron kuhn_boundary(int n, Keep keep) {
  const auto m = anisocert::geometry::kuhn_grid(n);
  Polyhedron p;
  p.vertices = m.vertices;
  std::map<std::array<int, 3>, std::vector<std::array<int, 3>>> faces;
  for (const auto& t : m.tetrahedra) {
    Rational lo[3] = {m.vertices[static_cast<std::size_t>(t[0])].x, m.vertices[static_cast<std::size_t>(t[0])].y, m.vertices[static_cast<std::size_t>(t[0])].z};
    for (const int v : t) {
      const auto& q = m.vertices[static_cast<std::size_t>(v)];
      lo[0] = std::min(lo[0], q.x), lo[1] = std::min(lo[1], q.y), lo[2] = std::min(lo[2], q.z);
    }
    if (!keep(lo[0].convert_to<int>(), lo[1].convert_to<int>(), lo[2].convert_to<int>())) continue;
    const auto [a, b, c, d] = t;
    for (const std::array<int, 3>& f : {std::array<int, 3>{b, c, d}, {a, d, c}, {a, b, d}, {a, c, b}}) {
      std::array<int, 3> s = f;
      std::sort(s.begin(), s.end());
      faces[s].push_back(f);
    }
  }
  for (const auto& [s, f] : faces)
    if (f.size() == 1) p.facets.push_back(f[0]);
  return p;
}

Polyhedron cube() { return kuhn_boundary(1, [](int, int, int) { return true; }); }

std::string defect(const Polyhedron& p) {
  const auto d = polyhedron_defect(p);
  return d ? *d : "none";
}

}  // namespace

TEST(Polyhedron, TheOutwardBoundaryOfASolidPasses) {
  EXPECT_EQ(defect(cube()), "none");
  EXPECT_EQ(defect(kuhn_boundary(2, [](int, int, int) { return true; })), "none");
  // L-shaped: one of the 2 × 2 × 1 cubes' layer left out, twice stacked (non-convex, reflex edges).
  EXPECT_EQ(defect(kuhn_boundary(2, [](int x, int y, int) { return !(x == 1 && y == 1); })), "none");
}

TEST(Polyhedron, EachDefectIsNamed) {
  Polyhedron open = cube();
  open.facets.pop_back();
  EXPECT_NE(defect(open).find("is in 1 facet: the surface is open"), std::string::npos) << defect(open);

  Polyhedron flipped = cube();
  std::swap(flipped.facets[3][1], flipped.facets[3][2]);
  EXPECT_NE(defect(flipped).find("runs the same way in its two facets"), std::string::npos) << defect(flipped);

  Polyhedron inward = cube();
  for (auto& f : inward.facets) std::swap(f[1], f[2]);
  EXPECT_NE(defect(inward).find("oriented inward"), std::string::npos) << defect(inward);

  // Two cubes of the 2 × 2 × 1 grid sharing an edge only, and two of the 2 × 2 × 2 grid sharing a vertex only.
  EXPECT_NE(defect(kuhn_boundary(2, [](int x, int y, int z) { return z == 0 && x == y; })).find("is in 4 facets: it is not a 2-manifold"),
            std::string::npos);
  EXPECT_NE(defect(kuhn_boundary(2, [](int x, int y, int z) { return x == y && y == z; })).find("is pinched"), std::string::npos);

  Polyhedron repeated = cube();
  repeated.facets[0][1] = repeated.facets[0][0];
  EXPECT_EQ(defect(repeated), "facet 0 names a vertex twice");
  Polyhedron out_of_range = cube();
  out_of_range.facets[2][2] = 8;
  EXPECT_EQ(defect(out_of_range), "facet 2 names vertex 8, not one of the 8 vertices");
  Polyhedron collinear = cube();
  collinear.vertices.push_back({Rational(1, 2), 0, 0});
  collinear.facets.push_back({0, 1, 8});
  collinear.vertices[1] = {1, 0, 0}, collinear.vertices[0] = {0, 0, 0};
  EXPECT_NE(defect(collinear).find("collinear"), std::string::npos) << defect(collinear);
}

// Facets that cross: a corner of the cube pushed through the opposite face (the enclosed volume
// stays positive, the surface crosses itself), and a second cube overlapping the first as one
// surface (two closed components that intersect: facets sharing no vertex).
TEST(Polyhedron, ASurfaceCrossingItselfIsNamed) {
  Polyhedron dent = cube();
  for (auto& v : dent.vertices)
    if (v.x == 1 && v.y == 1 && v.z == 1) v = {Rational(-1, 4), Rational(1, 2), Rational(1, 2)};
  EXPECT_NE(defect(dent).find("intersect: the surface crosses itself"), std::string::npos) << defect(dent);

  Polyhedron two = cube();
  const Polyhedron other = cube();
  const int offset = static_cast<int>(two.vertices.size());
  for (const auto& v : other.vertices) two.vertices.push_back({v.x + Rational(1, 2), v.y + Rational(1, 3), v.z + Rational(1, 4)});
  for (const auto& f : other.facets) two.facets.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  EXPECT_NE(defect(two).find("intersect: the surface crosses itself"), std::string::npos) << defect(two);

  // Touching at one point is meeting too: the second cube moved to touch the first at a corner.
  Polyhedron touching = cube();
  for (const auto& v : other.vertices) touching.vertices.push_back({v.x + 1, v.y + 1, v.z + 1});
  for (const auto& f : other.facets) touching.facets.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  EXPECT_NE(defect(touching).find("intersect"), std::string::npos) << defect(touching);
}

// The pair test itself, each case of sharing: sharing an edge (coplanar on one side: a fold; on
// both sides; off the plane), one vertex (coplanar sectors overlapping, touching only at the
// vertex, one edge along the other's; not coplanar, their planes' line inside both or outside
// one), none (apart, crossing, a vertex on the other's face, one inside the other in a plane).
TEST(Polyhedron, FacetsMeetDecidesEachWayOfSharing) {
  using anisocert::geometry::facets_meet;
  using P = anisocert::predicates::Point3<Rational>;
  const auto meet = [](std::vector<P> x, std::array<int, 3> t, std::array<int, 3> u) { return facets_meet(x, t, u); };
  // Shared edge 0–1 on the x axis, in the plane z = 0 unless said.
  EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 2, 0}}, {0, 1, 2}, {1, 0, 3}));   // fold
  EXPECT_FALSE(meet({{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, -2, 0}}, {0, 1, 2}, {1, 0, 3}));  // flat, opposite sides
  EXPECT_FALSE(meet({{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 1, 1}}, {0, 1, 2}, {1, 0, 3}));   // a ridge
  // Shared vertex 0.
  EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}, {3, 1, 0}}, {0, 1, 2}, {0, 3, 4}));   // sectors overlap
  EXPECT_FALSE(meet({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {-2, 0, 0}, {-2, -1, 0}}, {0, 1, 2}, {0, 3, 4}));  // opposite sectors
  EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 0, 0}, {1, -1, 0}}, {0, 1, 2}, {0, 3, 4}));   // edge 0–3 along 0–1
  EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, -1}, {1, 1, 1}}, {0, 1, 2}, {0, 3, 4}));   // crossing along a line from 0
  EXPECT_FALSE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, -1, -1}, {-1, -1, 1}}, {0, 1, 2}, {0, 3, 4}));  // that line outside one
  EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}, {1, 1, 1}}, {0, 1, 2}, {0, 3, 4}));   // touching along 0–(1, 1, 0)
  // Sharing none.
  EXPECT_FALSE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, {2, 0, 1}, {0, 2, 1}}, {0, 1, 2}, {3, 4, 5}));
  for (const std::array<int, 3>& u : {std::array<int, 3>{3, 4, 5}, {4, 3, 5}})  // the piercing edge either way
    EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {Rational(1, 2), Rational(1, 2), -1}, {Rational(1, 2), Rational(1, 2), 1}, {5, 5, 0}}, {0, 1, 2}, u));
  EXPECT_TRUE(meet({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {Rational(1, 2), Rational(1, 2), 0}, {1, 1, 1}, {0, 1, 1}}, {0, 1, 2}, {3, 4, 5}));
  EXPECT_TRUE(meet({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}}, {0, 1, 2}, {3, 4, 5}));
}
