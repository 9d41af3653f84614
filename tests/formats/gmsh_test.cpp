// The Gmsh .msh reader and writer (io/formats/gmsh.hpp): hand-written 2.2 and 4.1 files whose
// content is known line by line, files made by gmsh 4.8.4 (peers/gmsh, see its README), binary
// files built byte by byte in both byte orders, exact round trips through the writer, and the
// messages of the malformed catalogue's gmsh-* cases.
#include "io/formats/gmsh.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

namespace anisocert::io {
namespace {

namespace fs = std::filesystem;
using Metric = predicates::Sym2<Rational>;

const std::string peers = ANISOCERT_MALFORMED_DIR "/../peers/gmsh/";

Rational q(const char* text) { return parse_rational(text); }

// The message of reading text as a .msh file named "t.msh" ("" when it reads).
std::string error_of(const std::string& text) {
  try {
    read_gmsh(text, "t.msh");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_same(const MeshFile& a, const MeshFile& b) {
  ASSERT_EQ(a.mesh.sites.size(), b.mesh.sites.size());
  for (std::size_t i = 0; i < a.mesh.sites.size(); ++i) {
    EXPECT_EQ(a.mesh.sites[i].x, b.mesh.sites[i].x) << "site " << i;
    EXPECT_EQ(a.mesh.sites[i].y, b.mesh.sites[i].y) << "site " << i;
  }
  ASSERT_EQ(a.mesh.metrics.size(), b.mesh.metrics.size());
  for (std::size_t i = 0; i < a.mesh.metrics.size(); ++i) {
    EXPECT_EQ(a.mesh.metrics[i].m11, b.mesh.metrics[i].m11) << "metric " << i;
    EXPECT_EQ(a.mesh.metrics[i].m12, b.mesh.metrics[i].m12) << "metric " << i;
    EXPECT_EQ(a.mesh.metrics[i].m22, b.mesh.metrics[i].m22) << "metric " << i;
  }
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.edges, b.mesh.edges);
  EXPECT_EQ(a.edge_refs, b.edge_refs);
  EXPECT_EQ(a.triangle_refs, b.triangle_refs);
}

void expect_metric(const Metric& m, const Rational& m11, const Rational& m12, const Rational& m22) {
  EXPECT_EQ(m.m11, m11);
  EXPECT_EQ(m.m12, m12);
  EXPECT_EQ(m.m22, m22);
}

TEST(Gmsh, RecognizesItsFileByTheFirstToken) {
  EXPECT_TRUE(looks_like_gmsh("$MeshFormat\n4.1 0 8\n"));
  EXPECT_TRUE(looks_like_gmsh(" \r\n$MeshFormat\n"));
  EXPECT_FALSE(looks_like_gmsh("4 2 4\n0 0 1\n"));  // a FreeFem .msh: nv nt nbe
  EXPECT_FALSE(looks_like_gmsh("$Mesh"));
  EXPECT_FALSE(looks_like_gmsh(""));
}

// 2.2: sparse, unordered node tags (10, 3, 7, 20, 99), two points, lines with 2 tags,
// with none and with 3; the first tag is the reference.
const std::string v22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 7 "outer boundary"
2 3 "the $EndPhysicalNames is not here"
$EndPhysicalNames
$Nodes
5
10 0 0 0
3 1 0 0
7 1 1 0
20 0.1 1 0
99 5 5 0
$EndNodes
$Elements
7
1 15 2 0 1 10
2 1 2 7 1 10 3
3 1 0 3 7
4 2 2 3 1 10 3 7
5 2 3 3 1 4 10 7 20
6 15 2 3 1 20
7 1 3 8 2 1 20 10
$EndElements
)";

TEST(Gmsh, Reads22WithSparseTagsAndFirstTagReferences) {
  const MeshFile f = read_gmsh(v22, "v22.msh");
  // Sites in the order of $Nodes; node 99 is in no element and stays.
  ASSERT_EQ(f.mesh.sites.size(), 5u);
  EXPECT_EQ(f.mesh.sites[3].x, Rational(1, 10));  // "20 0.1 1 0": exactly 1/10
  EXPECT_EQ(f.mesh.sites[4].x, 5);
  // Tags 10, 3, 7, 20 are sites 0, 1, 2, 3; the points (type 15) are skipped.
  EXPECT_EQ(f.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(f.triangle_refs, (std::vector<int>{3, 3}));
  EXPECT_EQ(f.mesh.edges, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {3, 0}}));
  EXPECT_EQ(f.edge_refs, (std::vector<int>{7, 0, 8}));  // elements 2, 3 (no tag), 7
  EXPECT_EQ(f.vertex_refs, std::vector<int>(5, 0));
  EXPECT_TRUE(f.mesh.metrics.empty());
}

// 4.1: a point, a curve with two physical tags (11 first), a curve without any, a surface with
// physical tag 4; node blocks on each, the curve's parametric (one u per node); element blocks
// of points (skipped), lines, triangles and another point.
const std::string v41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Comments
a $Nodes word inside a section the reader skips
$EndComments
$Entities
1 2 1 0
1 0 0 0 0
5 0 0 0 1 0 0 2 11 12 2 1 -1
6 0 0 0 1 1 0 0 0
2 0 0 0 1 1 0 1 4 2 5 6
$EndEntities
$Nodes
3 4 2 40
0 1 0 1
40
0 0 0
1 5 1 2
2
30
1 0 0 0.5
1 1 0 0.75
2 2 0 1
8
0.5 1 0
$EndNodes
$Elements
5 6 1 6
0 1 15 1
1 40
1 5 1 2
2 40 2
3 2 30
1 6 1 1
4 30 8
2 2 2 1
5 40 2 8
0 1 15 1
6 30
$EndElements
)";

TEST(Gmsh, Reads41BlocksWithTheirEntitiesPhysicalTags) {
  const MeshFile f = read_gmsh(v41, "v41.msh");
  ASSERT_EQ(f.mesh.sites.size(), 4u);  // tags 40, 2, 30, 8 in block order
  EXPECT_EQ(f.mesh.sites[1].x, 1);
  EXPECT_EQ(f.mesh.sites[2].y, 1);  // "1 1 0 0.75": x y z, then u (skipped)
  EXPECT_EQ(f.mesh.sites[3].x, Rational(1, 2));
  EXPECT_EQ(f.mesh.edges, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 3}}));
  EXPECT_EQ(f.edge_refs, (std::vector<int>{11, 11, 0}));  // curve 5's first physical tag; curve 6 has none
  EXPECT_EQ(f.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 3}}));
  EXPECT_EQ(f.triangle_refs, (std::vector<int>{4}));
}

TEST(Gmsh, FailuresNameTheFileTheLineAndTheSection) {
  std::string bad = v41;
  bad.replace(bad.find("0.5 1 0"), 7, "0.5 1 x");
  // Line 26 holds node 8's coordinates.
  const std::string e = error_of(bad);
  EXPECT_EQ(e.rfind("t.msh:26: in $Nodes: the z of node 8: \"x\" is not an exact number", 0), 0u) << e;
}

TEST(Gmsh, RefusesWhatTheFormatForbids) {
  const auto with = [](std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  const std::vector<std::pair<std::string, std::string>> cases{
      {with(v41, "4.1 0 8", "3.0 0 8"), "t.msh:2: in $MeshFormat: version \"3.0\" is not supported"},
      {with(v41, "4.1 0 8", "4.1 0 4"), "t.msh:2: in $MeshFormat: data-size 4 is not supported"},
      {with(v22, "3 1 0 0", "10 1 0 0"), "in $Nodes: node 10 appears twice"},
      {with(v41, "3 4 2 40", "3 3 2 40"), "in $Nodes: numNodes is 3 but the blocks hold 4 nodes"},
      {with(v41, "5 6 1 6", "5 7 1 6"), "in $Elements: numElements is 7 but the blocks hold 6 elements"},
      {with(v41, "5 40 2 8", "5 40 2 9"), "in $Elements: element 5 refers to node 9, which is not in $Nodes"},
      {with(v41, "5 40 2 8", "5 40 2 8 30"), "in $Elements: element 5 (type 2) needs exactly 3 node tags on its line"},
      {with(v41, "$EndComments", "$EndComment"), "in $Comments: the file ends before \"$EndComments\""},
      {with(v41, "1 1 0 0.75", "1 1 1e-30 0.75"), "node 30 has z = 0.000000000000000000000000000001"},
      {with(v22, "10 0 0 0", "10 inf 0 0"), "in $Nodes: the x of node 10: \"inf\" is not an exact number"},
      {v41.substr(0, v41.size() - 13), "in $Elements: the file ends where \"$EndElements\" was expected"},
      {"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n0 0 0 0\n$EndElements\n$Entities\n0 0 0 0\n$EndEntities\n",
       "in $Entities: the section comes after $Elements"},
      {"$MeshFormat\n4.1 0 8\n$EndMeshFormat\nNodes\n", "t.msh:4: expected a section \"$Name\", found \"Nodes\""},
      {"$MeshFormat\n2.2 1 8\n", "binary MSH 2.2 is not supported"},
  };
  for (const auto& [text, message] : cases) EXPECT_NE(error_of(text).find(message), std::string::npos) << error_of(text);
}

// A 4.1 mesh of three nodes (sparse tags 5, 6, 7) and one triangle, with the given $NodeData.
std::string with_views(const std::string& views) {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 5 7\n2 1 0 3\n5\n6\n7\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
         "$Elements\n1 1 1 1\n2 1 2 1\n1 5 6 7\n$EndElements\n" +
         views;
}

std::string view(int components, const std::vector<std::string>& records) {
  std::string v = "$NodeData\n1\n\"a view\"\n1\n0.0\n3\n0\n" + std::to_string(components) + "\n" +
                  std::to_string(records.size()) + "\n";
  for (const std::string& r : records) v += r + "\n";
  return v + "$EndNodeData\n";
}

TEST(Gmsh, NineComponentMetricIsTheUpperLeftBlockOfASymmetricTensor) {
  // The z row and column (0.3, 0.7, 9) are not the planar metric's.
  const MeshFile f = read_gmsh(with_views(view(9, {"7 4 0.5 0.3 0.5 2 0.7 0.3 0.7 9", "5 1 0 0 0 1 0 0 0 1",
                                                   "6 2 -0.25 0 -0.25 3 0 0 0 1"})),
                               "m.msh");
  ASSERT_EQ(f.mesh.metrics.size(), 3u);
  expect_metric(f.mesh.metrics[0], 1, 0, 1);                       // node 5
  expect_metric(f.mesh.metrics[1], 2, Rational(-1, 4), 3);         // node 6
  expect_metric(f.mesh.metrics[2], 4, Rational(1, 2), 2);          // node 7
}

TEST(Gmsh, SizeAndThreeComponentMetrics) {
  // One component: a size h, the metric I/h² exactly (1/0.1² = 100, 1/3² = 1/9).
  const MeshFile sizes = read_gmsh(with_views(view(1, {"5 0.1", "6 3", "7 0.5"})), "h.msh");
  expect_metric(sizes.mesh.metrics[0], 100, 0, 100);
  expect_metric(sizes.mesh.metrics[1], Rational(1, 9), 0, Rational(1, 9));
  expect_metric(sizes.mesh.metrics[2], 4, 0, 4);
  // Three components: m11 m12 m22.
  const MeshFile three = read_gmsh(with_views(view(3, {"6 2 1 3", "5 1 0 1", "7 5 -2 1"})), "m3.msh");
  expect_metric(three.mesh.metrics[1], 2, 1, 3);
  expect_metric(three.mesh.metrics[2], 5, -2, 1);
}

TEST(Gmsh, TheFirstViewWithOneThreeOrNineComponentsIsTheMetric) {
  // A vector view (2 components) first, skipped; the size view; a 9-component view after it is
  // not read (it is not even symmetric).
  const MeshFile f = read_gmsh(with_views(view(2, {"5 1 1", "6 1 1", "7 1 1"}) + view(1, {"5 2", "6 2", "7 2"}) +
                                          view(9, {"5 1 2 0 3 1 0 0 0 1"})),
                               "views.msh");
  ASSERT_EQ(f.mesh.metrics.size(), 3u);
  for (const Metric& m : f.mesh.metrics) expect_metric(m, Rational(1, 4), 0, Rational(1, 4));
  EXPECT_TRUE(read_gmsh(with_views(view(2, {"5 1 1", "6 1 1", "7 1 1"})), "v.msh").mesh.metrics.empty());
}

TEST(Gmsh, RefusesAMetricThatIsNotOneSymmetricPositiveDefiniteValuePerNode) {
  const std::string ok = "5 1 0 0 0 1 0 0 0 1";
  const std::vector<std::pair<std::string, std::string>> cases{
      {view(9, {ok, "6 1 0.5 0 0.25 1 0 0 0 1", "7 1 0 0 0 1 0 0 0 1"}),
       "in $NodeData: the tensor of node 6, [1, 0.5, 0, 0.25, 1, 0, 0, 0, 1], is not symmetric"},
      {view(9, {ok, "6 1 0 1 0 1 0 2 0 1", "7 1 0 0 0 1 0 0 0 1"}), "value 3 is 1 but value 7 is 2"},  // m13 ≠ m31
      {view(9, {ok, "6 1 0 0 0 1 0 0 0 1", "7 1 2 0 2 1 0 0 0 1"}),
       "in $NodeData: the metric of node 7, [m11, m12, m22] = [1, 2, 1]"},
      {view(3, {"5 1 0 1", "6 0 0 1", "7 1 0 1"}), "the metric of node 6, [m11, m12, m22] = [0, 0, 1]"},
      {view(1, {"5 1", "6 -2", "7 1"}), "the size of node 6 is -2, not positive"},
      {view(1, {"5 1", "7 1"}), "in $NodeData: node 6 has no value: the view has 2 values for 3 nodes"},
      {view(1, {"5 1", "6 1", "5 1"}), "in $NodeData: node 5 has two values"},
      {view(1, {"5 1", "6 1", "8 1"}), "the view gives a value to node 8, which is not in $Nodes"},
      {view(1, {"5 1", "6 nan", "7 1"}), "value 1 of node 6: \"nan\" is not an exact number"},
  };
  for (const auto& [views, message] : cases) {
    const std::string e = error_of(with_views(views));
    EXPECT_NE(e.find(message), std::string::npos) << e;
  }
}

// A binary .msh built by hand, in either byte order: the reader must take the file's, given by
// the int 1 after the $MeshFormat line.
class Bytes {
 public:
  explicit Bytes(bool big_endian) : swap_(big_endian != (std::endian::native == std::endian::big)) {}
  Bytes& text(std::string_view t) {
    s_ += t;
    return *this;
  }
  Bytes& i32(std::int32_t v) { return raw(v); }
  Bytes& u64(std::uint64_t v) { return raw(v); }
  Bytes& f64(double v) { return raw(v); }
  const std::string& str() const { return s_; }

 private:
  template <class T>
  Bytes& raw(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (swap_) std::reverse(b, b + sizeof(T));
    s_.append(b, sizeof(T));
    return *this;
  }
  bool swap_;
  std::string s_;
};

// § MSH file format, 4.1 binary: a curve with physical tag 9 and a surface; nodes 7, 3, 5 at
// (0.1, 0), (1, 0), (0, 1) — 0.1 the double nearest 1/10; two lines, a point (skipped: 1 node
// tag), a triangle; a 3-component $NodeData (tags ints).
std::string hand_binary(bool big_endian) {
  Bytes b(big_endian);
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  b.text("$Entities\n").u64(0).u64(1).u64(1).u64(0);
  b.i32(4).f64(0).f64(0).f64(0).f64(1).f64(1).f64(0).u64(1).i32(9).u64(0);
  b.i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(0).u64(0).u64(0).text("\n$EndEntities\n");
  b.text("$Nodes\n").u64(1).u64(3).u64(3).u64(7).i32(2).i32(1).i32(0).u64(3).u64(7).u64(3).u64(5);
  b.f64(0.1).f64(0).f64(0).f64(1).f64(0).f64(0).f64(0).f64(1).f64(0).text("\n$EndNodes\n");
  b.text("$Elements\n").u64(3).u64(4).u64(1).u64(4);
  b.i32(1).i32(4).i32(1).u64(2).u64(1).u64(7).u64(3).u64(2).u64(3).u64(5);
  b.i32(0).i32(1).i32(15).u64(1).u64(3).u64(7);
  b.i32(2).i32(1).i32(2).u64(1).u64(4).u64(7).u64(3).u64(5).text("\n$EndElements\n");
  b.text("$NodeData\n1\n\"m\"\n1\n0\n3\n0\n3\n3\n");
  b.i32(3).f64(2).f64(0.5).f64(3).i32(5).f64(1).f64(0).f64(1).i32(7).f64(4).f64(-1).f64(1).text("\n$EndNodeData\n");
  return b.str();
}

TEST(Gmsh, ReadsBinaryInEitherByteOrder) {
  const MeshFile little = read_gmsh(hand_binary(false), "little.msh");
  const MeshFile big = read_gmsh(hand_binary(true), "big.msh");
  expect_same(little, big);
  ASSERT_EQ(big.mesh.sites.size(), 3u);
  EXPECT_EQ(big.mesh.sites[0].x, Rational(0.1));  // the double 0.1, exactly: not 1/10
  EXPECT_NE(big.mesh.sites[0].x, Rational(1, 10));
  EXPECT_EQ(big.mesh.sites[2].y, 1);
  EXPECT_EQ(big.mesh.edges, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
  EXPECT_EQ(big.edge_refs, (std::vector<int>{9, 9}));
  EXPECT_EQ(big.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}}));
  ASSERT_EQ(big.mesh.metrics.size(), 3u);
  expect_metric(big.mesh.metrics[0], 4, -1, 1);               // node 7
  expect_metric(big.mesh.metrics[1], 2, Rational(1, 2), 3);   // node 3
}

// § $PartitionedEntities, 4.1 binary: a curve whose parent is a surface (parentDim 2 > 1) is a
// partition interface, and its elements are skipped by their node count whatever their type: here
// a 9-node quadrangle (type 10), then the surface's triangle. Campaign mutant 199 skipped 18 node
// tags for type 10 and read the triangle's block as node tags.
TEST(Gmsh, ElementsOnAPartitionInterfaceAreSkippedByTheirNodeCount) {
  Bytes b(false);
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  b.text("$PartitionedEntities\n").u64(1).u64(0).u64(0).u64(1).u64(1).u64(0);
  b.i32(4).i32(2).i32(1).u64(1).i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(0).u64(1).i32(9).u64(0);
  b.i32(1).i32(2).i32(1).u64(1).i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(0).u64(0).u64(0).text("\n$EndPartitionedEntities\n");
  b.text("$Nodes\n").u64(1).u64(3).u64(3).u64(7).i32(2).i32(1).i32(0).u64(3).u64(7).u64(3).u64(5);
  b.f64(0).f64(0).f64(0).f64(1).f64(0).f64(0).f64(0).f64(1).f64(0).text("\n$EndNodes\n");
  b.text("$Elements\n").u64(2).u64(2).u64(1).u64(2);
  b.i32(1).i32(4).i32(10).u64(1).u64(1);
  for (int k = 0; k < 9; ++k) b.u64(7);
  b.i32(2).i32(1).i32(2).u64(1).u64(2).u64(7).u64(3).u64(5).text("\n$EndElements\n");
  const MeshFile f = read_gmsh(b.str(), "partitioned.msh");
  EXPECT_EQ(f.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}}));
  EXPECT_TRUE(f.mesh.edges.empty());
}

TEST(Gmsh, BinaryFailuresNameTheByteAndTheSection) {
  const std::string file = hand_binary(true);
  const std::size_t nodes = file.find("$Nodes\n") + 7;
  // Cut inside node 3's coordinates: 4 sizes, a block header (3 ints, a size), 3 tags, 4 doubles.
  const std::size_t cut = nodes + 32 + 20 + 24 + 32 + 3;
  EXPECT_EQ(error_of(file.substr(0, cut)),
            "t.msh: byte " + std::to_string(cut - 3) + ": in $Nodes: the file ends inside the y of node 3 (8 bytes needed)");
  // The point's type made unknown: its node tags cannot be skipped.
  std::string unknown = file;
  // After the header (4 sizes) and the line block (3 ints, a size, 2 lines of 3 sizes): the
  // point block's entityDim, entityTag, then its elementType, big-endian 15.
  const std::size_t quad = file.find("$Elements\n") + 10 + 32 + 20 + 2 * 24 + 8;
  unknown[quad + 3] = 100;
  EXPECT_NE(error_of(unknown).find("in $Elements: element 3 has type 100, whose number of nodes the manual does not list"),
            std::string::npos)
      << error_of(unknown);
  std::string order = hand_binary(false);
  order[order.find("4.1 1 8\n") + 8] = 2;  // the little-endian int 1 became 2
  EXPECT_EQ(error_of(order),
            "t.msh: byte 20: in $MeshFormat: the int that gives the byte order is 2, not 1 in either byte order");
}

// Tetrahedra (type 4) make the mesh tetrahedral (issue 39): a 2.2 file of one tetrahedron, its
// four faces as triangles with physical tag 2, node 4 at z = 1/2 (no longer refused), tags
// sparse; the metric view's 9 values become the 3×3 metric (m11 m12 m13 m22 m23 m33), a
// 1-component view I/h², a 3-component view is a vector in 3D and skipped.
std::string tetrahedron22(const std::string& views) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n9 0 0 0.5\n$EndNodes\n"
         "$Elements\n5\n1 2 2 2 1 1 3 2\n2 2 2 2 1 1 2 9\n3 2 2 2 1 2 3 9\n4 2 2 2 1 3 1 9\n5 4 2 7 1 1 2 3 9\n$EndElements\n" +
         views;
}

TEST(Gmsh, TetrahedraMakeATetrahedralMesh) {
  const MeshFile f = read_gmsh(tetrahedron22(""), "tet.msh");
  ASSERT_EQ(f.dimension, 3);
  ASSERT_EQ(f.mesh3.vertices.size(), 4u);
  EXPECT_EQ(f.mesh3.vertices[3].z, Rational(1, 2));
  EXPECT_TRUE(f.mesh.sites.empty());
  EXPECT_EQ(f.mesh3.tetrahedra, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}}));
  EXPECT_EQ(f.tetrahedron_refs, std::vector<int>{7});
  EXPECT_EQ(f.mesh3.triangles.size(), 4u);
  EXPECT_EQ(f.triangle_refs, std::vector<int>(4, 2));
  EXPECT_TRUE(f.mesh.triangles.empty());
  const MeshFile m = read_gmsh(tetrahedron22(view(9, {"1 4 1 2 1 5 3 2 3 9", "2 1 0 0 0 1 0 0 0 1", "3 1 0 0 0 1 0 0 0 1",
                                                      "9 1 0 0 0 1 0 0 0 1"})),
                               "m.msh");
  ASSERT_EQ(m.mesh3.metrics.size(), 4u);
  EXPECT_EQ(m.mesh3.metrics[0], (predicates::Sym3<Rational>{4, 1, 2, 5, 3, 9}));
  const MeshFile h = read_gmsh(tetrahedron22(view(3, {"1 1 0 0", "2 1 0 0", "3 1 0 0", "9 1 0 0"}) +
                                             view(1, {"1 0.5", "2 0.5", "3 0.5", "9 0.5"})),
                               "h.msh");
  ASSERT_EQ(h.mesh3.metrics.size(), 4u);
  EXPECT_EQ(h.mesh3.metrics[2], (predicates::Sym3<Rational>{4, 0, 0, 4, 0, 4}));
  // Refused: a 3D metric with a negative leading minor of order 2 (diag(−1, −1, 1) has det 1);
  // an asymmetric tensor; a hexahedron; a tetrahedron's fifth node tag.
  const std::string identity = "2 1 0 0 0 1 0 0 0 1\n3 1 0 0 0 1 0 0 0 1\n9 1 0 0 0 1 0 0 0 1";
  const std::vector<std::pair<std::string, std::string>> cases{
      {tetrahedron22(view(9, {"1 -1 0 0 0 -1 0 0 0 1", identity})),
       "in $NodeData: the metric of node 1, [m11, m12, m13, m22, m23, m33] = [-1, 0, 0, -1, 0, 1]"},
      {tetrahedron22(view(9, {"1 1 0 0.5 0 1 0 0 0 1", identity})), "value 3 is 0.5 but value 7 is 0"},
      {tetrahedron22("").replace(tetrahedron22("").find("5 4 2 7 1 1 2 3 9"), 17, "5 5 2 7 1 1 2 3 9 1 2 3 9"),
       "in $Elements: element 5 is an 8-node hexahedron (type 5): anisocert certifies meshes of 3-node triangles or 4-node tetrahedra only"},
      {tetrahedron22("").replace(tetrahedron22("").find("5 4 2 7 1 1 2 3 9"), 17, "5 4 2 7 1 1 2 3 9 9"),
       "in $Elements: element 5 (type 4) needs exactly 4 node tags on its line"},
  };
  for (const auto& [text, message] : cases) EXPECT_NE(error_of(text).find(message), std::string::npos) << error_of(text);
  // Without the tetrahedron, z = 1/2 is refused.
  std::string flat = tetrahedron22("");
  flat.replace(flat.find("5\n1 2 2"), 1, "4").replace(flat.find("5 4 2 7 1 1 2 3 9\n"), 18, "");
  EXPECT_NE(error_of(flat).find("node 9 has z = 0.5, and there is no tetrahedron"), std::string::npos) << error_of(flat);
}

// The writer writes a tetrahedral mesh back (4.1, ASCII and binary): the same vertices, z
// included, tetrahedra, triangles, references and 3×3 metrics.
TEST(Gmsh, TetrahedralMeshesAreWrittenBackExactly) {
  const MeshFile f = read_gmsh(tetrahedron22(view(9, {"1 4 1 2 1 5 3 2 3 9", "2 1 0 0 0 1 0 0 0 1", "3 2 0 0 0 1 0 0 0 1",
                                                      "9 1 0 0 0 1 0 0 0 0.25"})),
                               "m.msh");
  for (const GmshEncoding e : {GmshEncoding::ascii, GmshEncoding::binary}) {
    const MeshFile g = read_gmsh(gmsh_text(f, e), "again.msh");
    ASSERT_EQ(g.dimension, 3);
    EXPECT_EQ(g.mesh3.vertices.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(g.mesh3.vertices[i].z, f.mesh3.vertices[i].z);
      EXPECT_EQ(g.mesh3.metrics[i], f.mesh3.metrics[i]);
    }
    EXPECT_EQ(g.mesh3.tetrahedra, f.mesh3.tetrahedra);
    EXPECT_EQ(g.tetrahedron_refs, f.tetrahedron_refs);
    EXPECT_EQ(g.mesh3.triangles, f.mesh3.triangles);
    EXPECT_EQ(g.triangle_refs, f.triangle_refs);
  }
}

TEST(Gmsh, HostileCountsFailWithoutAllocating) {
  Bytes b(false);
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n");
  b.text("$Nodes\n").u64(1).u64(std::uint64_t{1} << 60).u64(1).u64(std::uint64_t{1} << 60);
  b.i32(2).i32(1).i32(0).u64(std::uint64_t{1} << 60).u64(1).text("\n$EndNodes\n");
  EXPECT_NE(error_of(b.str()).find("in $Nodes: the file ends inside a nodeTag"), std::string::npos) << error_of(b.str());
}

TEST(Gmsh, BinarySectionsAreSkippedByTheirStructureNotByTheirText) {
  // $ElementData, $ElementNodeData and an unused $NodeData view whose binary values hold the text
  // of their own end line: a reader searching for "$End..." would stop inside them.
  const auto section = [](const std::string& name, bool per_element_node) {
    std::string values = "\n$End" + name + "\n";
    values.resize((values.size() + 7) / 8 * 8, '\0');  // 2 doubles for $NodeData: not a metric view
    Bytes b(false);
    b.text("$" + name + "\n1\n\"v\"\n0\n3\n0\n" + std::to_string(values.size() / 8) + "\n1\n").i32(1);
    if (per_element_node) b.i32(1);
    return b.text(values).text("\n$End" + name + "\n").str();
  };
  const std::string file =
      hand_binary(false) + section("ElementData", false) + section("ElementNodeData", true) + section("NodeData", false);
  const MeshFile f = read_gmsh(file, "sections.msh");
  EXPECT_EQ(f.mesh.triangles.size(), 1u);
  EXPECT_EQ(f.mesh.metrics.size(), 3u);
}

TEST(Gmsh, BinaryPeriodicGhostAndParametrizationSectionsAreReadToTheirEnd) {
  // Each section as § MSH file format 4.1 lays it out, with its first count n: the file reads
  // with the count the section holds, and fails with one more (a reader skipping to the
  // "$End..." text would take both).
  const std::vector<std::pair<std::string, std::function<void(Bytes&, std::uint64_t)>>> sections{
      {"Periodic",
       [](Bytes& b, std::uint64_t n) {
         b.u64(n).i32(1).i32(3).i32(1).u64(16);  // a link: curve 3 on curve 1, 16 affine values
         for (int i = 0; i < 16; ++i) b.f64(i % 5 == 0 ? 1 : 0);
         b.u64(2).u64(3).u64(7).u64(5).u64(7);   // 2 corresponding node pairs
       }},
      {"GhostElements",
       [](Bytes& b, std::uint64_t n) {
         b.u64(n).u64(4).i32(1).u64(2).i32(2).i32(3);  // element 4 of partition 1, ghost in 2 and 3
       }},
      {"Parametrizations",
       [](Bytes& b, std::uint64_t n) {
         b.u64(n).u64(1).i32(4).u64(2);  // curve 4, 2 nodes: X Y Z U each
         for (int i = 0; i < 8; ++i) b.f64(0.5);
         b.i32(1).u64(3).u64(1);  // surface 1, 3 nodes of 11 reals, 1 triangle of 3 ints
         for (int i = 0; i < 33; ++i) b.f64(0.25);
         b.i32(0).i32(1).i32(2);
       }},
  };
  for (const auto& [name, write] : sections) {
    for (std::uint64_t n : {1, 2}) {
      Bytes b(false);
      b.text("$" + name + "\n");
      write(b, n);
      const std::string e = error_of(hand_binary(false) + b.text("\n$End" + name + "\n").str());
      if (n == 1) EXPECT_EQ(e, "") << name;
      else EXPECT_NE(e.find("in $" + name + ": "), std::string::npos) << name << ": " << e;
    }
  }
}

MeshFile exact_mesh() {
  MeshFile m;
  m.mesh.sites = {{0, 0}, {q("0.1"), q("-0.375")}, {q("12.5"), q("1e-20")}, {q("-3"), q("2.5")}, {7, 7}};
  m.mesh.metrics = {{1, 0, 1}, {q("0.1"), q("-0.05"), 3}, {q("1e10"), 0, q("1e-10")}, {2, 1, 2}, {1, 0, 1}};
  m.mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 2, 3}};
  m.triangle_refs = {1, 1, 2};
  m.mesh.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {1, 3}};
  m.edge_refs = {5, 5, 0, 7, 5};  // 5 twice apart: two blocks on one curve, the order kept
  return m;
}

TEST(Gmsh, AsciiRoundTripIsExact) {
  const MeshFile m = exact_mesh();
  const std::string text = gmsh_text(m);
  EXPECT_NE(text.find("\n0.1 -0.375 0\n"), std::string::npos);  // exact decimals
  expect_same(read_gmsh(text, "ascii.msh"), m);
  EXPECT_EQ(write_gmsh_file(m, "out.msh").front().content, text);
}

TEST(Gmsh, BinaryRoundTripIsExact) {
  MeshFile m = exact_mesh();
  m.mesh.sites[1] = {Rational(0.1), Rational(1.0 / 3)};  // doubles, not 1/10 and 1/3
  m.mesh.sites[2].y = Rational(1e-20);
  m.mesh.metrics[1] = {Rational(0.1), Rational(-0.05), 3};
  m.mesh.metrics[2] = {Rational(1e10), 0, Rational(1e-10)};
  expect_same(read_gmsh(gmsh_text(m, GmshEncoding::binary), "binary.msh"), m);
}

TEST(Gmsh, RoundTripOfSitesAlone) {
  MeshFile m;
  m.mesh.sites = {{1, 2}, {3, 4}};
  for (GmshEncoding e : {GmshEncoding::ascii, GmshEncoding::binary}) expect_same(read_gmsh(gmsh_text(m, e), "s.msh"), m);
}

TEST(Gmsh, WritersRefuseWhatTheirEncodingCannotHoldExactly) {
  MeshFile m = exact_mesh();
  m.mesh.sites[4].y = Rational(1, 3);
  EXPECT_THROW(
      {
        try {
          gmsh_text(m);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("1/3 has no finite decimal expansion"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  m.mesh.sites[4].y = q("0.1");  // a finite decimal, not a double
  EXPECT_NO_THROW(gmsh_text(m));
  EXPECT_THROW(
      {
        try {
          gmsh_text(m, GmshEncoding::binary);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("is not a double"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
}

// peers/gmsh/square-hole.geo: 20 nodes, 28 triangles on physical surface 1, 8 lines on the
// outer boundary (physical curve 10) and 4 on the hole (physical curve 20).
void expect_square_hole(const MeshFile& f) {
  EXPECT_EQ(f.mesh.sites.size(), 20u);
  EXPECT_EQ(f.mesh.triangles.size(), 28u);
  EXPECT_EQ(f.triangle_refs, std::vector<int>(28, 1));
  std::vector<int> refs = f.edge_refs;
  std::sort(refs.begin(), refs.end());
  std::vector<int> expected(8, 10);
  expected.resize(12, 20);
  EXPECT_EQ(refs, expected);
}

TEST(Gmsh, PeerSquareHoleInEveryEncoding) {
  const MeshFile a41 = read_gmsh_file(peers + "square-hole-41.msh");
  const MeshFile a22 = read_gmsh_file(peers + "square-hole-22.msh");
  const MeshFile b41 = read_gmsh_file(peers + "square-hole-41-bin.msh");
  for (const MeshFile* f : {&a41, &a22, &b41}) expect_square_hole(*f);
  expect_same(a41, a22);  // the same text, %.16g, in both versions
  // Node 5 is Point(5) = {0.4, 0.4, 0}: the decimal 0.4 in ASCII, the double 0.4 in binary.
  EXPECT_EQ(a41.mesh.sites[4].x, Rational(2, 5));
  EXPECT_EQ(b41.mesh.sites[4].x, Rational(0.4));
  EXPECT_EQ(a41.mesh.triangles, b41.mesh.triangles);
  EXPECT_EQ(a41.mesh.edges, b41.mesh.edges);
  for (std::size_t i = 0; i < a41.mesh.sites.size(); ++i)  // 16 significant digits
    EXPECT_LT(abs(a41.mesh.sites[i].x - b41.mesh.sites[i].x) + abs(a41.mesh.sites[i].y - b41.mesh.sites[i].y),
              Rational(1, 1000000000000000))
        << "node " << i + 1;
}

std::vector<std::pair<Rational, Rational>> sorted_sites(const MeshFile& f) {
  std::vector<std::pair<Rational, Rational>> s;
  for (const auto& p : f.mesh.sites) s.emplace_back(p.x, p.y);
  std::sort(s.begin(), s.end());
  return s;
}

TEST(Gmsh, PeerBinarySectionsReadByStructure) {
  const MeshFile plain = read_gmsh_file(peers + "square-hole-41-bin.msh");
  // Parametric coordinates after each node's x y z: the same nodes, in the same order.
  expect_same(read_gmsh_file(peers + "square-hole-41-param-bin.msh"), plain);
  // Two partitions: $PartitionedEntities (the blocks' entities), $GhostElements; the lines on
  // the interface between the partitions are no boundary.
  const MeshFile parts = read_gmsh_file(peers + "square-hole-41-part-bin.msh");
  expect_square_hole(parts);
  EXPECT_EQ(sorted_sites(parts), sorted_sites(plain));
  // $Periodic (peers/gmsh/periodic.geo): 8 lines on physical curve 5, triangles on surface 6.
  const MeshFile periodic = read_gmsh_file(peers + "periodic-41-bin.msh");
  EXPECT_EQ(periodic.edge_refs, std::vector<int>(8, 5));
  EXPECT_EQ(periodic.mesh.triangles.size(), periodic.triangle_refs.size());
  EXPECT_EQ(periodic.triangle_refs, std::vector<int>(periodic.triangle_refs.size(), 6));
  EXPECT_FALSE(periodic.mesh.triangles.empty());
}

TEST(Gmsh, PeerBinaryMetricIsTheDoublesOfTheHandWrittenOne) {
  const MeshFile text = read_gmsh_file(peers + "metric-hand-written.msh");
  const MeshFile binary = read_gmsh_file(peers + "metric-41-bin.msh");  // with an $InterpolationScheme
  EXPECT_EQ(binary.mesh.triangles, text.mesh.triangles);
  EXPECT_EQ(binary.edge_refs, (std::vector<int>{3, 3, 3, 3}));
  ASSERT_EQ(binary.mesh.metrics.size(), 4u);
  // Sites in the order of the tags 12, 3, 7, 5: node 3 is "3 4 0.1 0 0.1 1 ...".
  expect_metric(text.mesh.metrics[1], 4, Rational(1, 10), 1);
  expect_metric(binary.mesh.metrics[1], 4, Rational(0.1), 1);
  expect_metric(text.mesh.metrics[2], 100, 0, Rational(1, 100));  // node 7
  expect_metric(binary.mesh.metrics[2], 100, 0, Rational(0.01));
  expect_metric(binary.mesh.metrics[3], 2, Rational(-1, 2), 2);  // node 5: -0.5 is a double
}

// The malformed catalogue's gmsh-* cases (run through `anisocert certify` by
// malformed_catalogue_test.cpp): the reader's message contains the case's and names the file.
TEST(Gmsh, MalformedCatalogueMessagesAreTheReaders) {
  int cases = 0;
  for (const auto& d : fs::directory_iterator(ANISOCERT_MALFORMED_DIR)) {
    if (d.path().filename().string().rfind("gmsh-", 0) != 0) continue;
    ++cases;
    std::ifstream in(d.path() / "case.json");
    const nlohmann::json c = nlohmann::json::parse(in);
    const std::string mesh = (d.path() / c["mesh"].get<std::string>()).string();
    try {
      read_gmsh_file(mesh);
      ADD_FAILURE() << mesh << " reads";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind(mesh, 0), 0u) << m;
      EXPECT_NE(m.find(c["message"].get<std::string>()), std::string::npos) << m;
    }
  }
  EXPECT_GE(cases, 14);
}

}  // namespace
}  // namespace anisocert::io
