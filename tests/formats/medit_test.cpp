// Medit .mesh/.meshb and .sol/.solb (io/formats/medit.hpp): files of known content in the layouts
// MMG and libMeshb write (a keyword and its value on separate lines, comments, keywords we skip),
// the writer's files in every version and both encodings read back exactly, binary files in the
// other byte order, and malformed files refused with the file, the line or byte, and the keyword.
#include "io/formats/medit.hpp"

#include <array>
#include <vector>

#include "format_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

namespace {

using anisocert::test_support::error_of;

using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::predicates::Sym2;
using namespace anisocert::io;


// Two triangles of the unit square, a boundary edge per side, a corner, a required edge; metrics
// that are decimals (not doubles) or dyadic (doubles), per the test.
MeshFile square(bool dyadic) {
  MeshFile f;
  const Rational h = dyadic ? Rational(1, 2) : parse_rational("0.1");
  f.mesh.sites = {{0, 0}, {1, 0}, {1, h}, {0, h}};
  f.vertex_refs = {1, 2, 3, 4};
  f.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  f.triangle_refs = {7, 8};
  f.mesh.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  f.edge_refs = {1, 2, 3, 4};
  f.corners = {0, 2};
  f.required_vertices = {1};
  f.required_edges = {3};
  f.ridges = {0};
  f.mesh.metrics = {{4, Rational(1, 4), 2}, {h, 0, h}, {1, 0, 1}, {Rational(3, 2), Rational(-1, 2), 1}};
  return f;
}

void expect_same(const MeshFile& a, const MeshFile& b) {
  EXPECT_EQ(a.mesh.sites.size(), b.mesh.sites.size());
  for (std::size_t i = 0; i < std::min(a.mesh.sites.size(), b.mesh.sites.size()); ++i) {
    EXPECT_EQ(a.mesh.sites[i].x, b.mesh.sites[i].x) << i;
    EXPECT_EQ(a.mesh.sites[i].y, b.mesh.sites[i].y) << i;
  }
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.edges, b.mesh.edges);
  EXPECT_EQ(a.vertex_refs, b.vertex_refs);
  EXPECT_EQ(a.edge_refs, b.edge_refs);
  EXPECT_EQ(a.triangle_refs, b.triangle_refs);
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.required_vertices, b.required_vertices);
  EXPECT_EQ(a.required_edges, b.required_edges);
  EXPECT_EQ(a.ridges, b.ridges);
}

void expect_same_metrics(const std::vector<Sym2<Rational>>& a, const std::vector<Sym2<Rational>>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].m11, b[i].m11) << i;
    EXPECT_EQ(a[i].m12, b[i].m12) << i;
    EXPECT_EQ(a[i].m22, b[i].m22) << i;
  }
}

// Every 4- or 8-byte word of a binary Medit file reversed: the file as a machine of the other byte
// order writes it. The layout (libMeshb): words of 4 bytes, except reals (versions 2-4), positions
// (versions 3-4) and integers (version 4) of 8 — we rebuild it by writing the same file with the
// sizes known: here by re-encoding through the layout's own word list.
std::string swapped(const std::string& bytes, const std::vector<int>& widths) {
  std::string out = bytes;
  std::size_t at = 0;
  for (int w : widths) {
    std::reverse(out.begin() + static_cast<std::ptrdiff_t>(at), out.begin() + static_cast<std::ptrdiff_t>(at + w));
    at += w;
  }
  EXPECT_EQ(at, bytes.size());
  return out;
}

TEST(Medit, AsciiAsMmgWritesIt) {
  // MMG's layout: keyword and value on separate lines, a comment, a keyword we do not read
  // (Normals, whose data are numbers), the 3D-only keyword Tetrahedra with 0 entries.
  const char* text =
      "MeshVersionFormatted\n2\n\nDimension\n2\n# a comment line\nVertices\n3\n"
      "0 0 1\n1.5 0 2\n0.1 2e-1 3\n"
      "Normals\n1\n0.0 1.0\nTetrahedra\n0\n"
      "Triangles\n1\n1 2 3 5\nEdges\n1\n1 2 9\nRequiredEdges\n1\n1\nEnd\n";
  const MeshFile f = read_medit(text, "mmg.mesh");
  ASSERT_EQ(f.mesh.sites.size(), 3u);
  EXPECT_EQ(f.mesh.sites[2].x, Rational(1, 10));  // the decimal 0.1 is 1/10 exactly
  EXPECT_EQ(f.mesh.sites[2].y, Rational(1, 5));
  EXPECT_EQ(f.vertex_refs, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(f.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}}));
  EXPECT_EQ(f.triangle_refs, std::vector<int>{5});
  EXPECT_EQ(f.mesh.edges, (std::vector<std::pair<int, int>>{{0, 1}}));
  EXPECT_EQ(f.mesh.segments, (std::vector<std::pair<int, int>>{{0, 1}}));  // a required edge is a constrained segment
}

TEST(Medit, RoundTripsEveryVersionAndEncoding) {
  for (const bool dyadic : {false, true})
    for (const MeditEncoding e : {MeditEncoding::ascii, MeditEncoding::binary})
      for (int version = 1; version <= 4; ++version) {
        SCOPED_TRACE("version " + std::to_string(version) + (e == MeditEncoding::binary ? " binary" : " ascii") +
                     (dyadic ? " dyadic" : " decimal"));
        const MeshFile f = square(dyadic);
        if (e == MeditEncoding::binary && !dyadic) {
          // 1/10 is not a double: the binary writer refuses it rather than round it.
          EXPECT_NE(error_of([&] { medit_mesh_text(f, e, version); }).find("is not a double"), std::string::npos);
          continue;
        }
        const std::string mesh = medit_mesh_text(f, e, version), sol = medit_sol_text(f.mesh.metrics, e, version);
        expect_same(read_medit(mesh, "m"), f);
        expect_same_metrics(read_medit_sol(sol, "s"), f.mesh.metrics);
      }
}

TEST(Medit, BinaryInTheOtherByteOrder) {
  MeshFile f;
  f.mesh.sites = {{0, 0}, {1, 0}, {0, Rational(1, 4)}};
  f.mesh.triangles = {{0, 1, 2}};
  f.vertex_refs = {0, 0, 0};
  f.triangle_refs = {3};
  // Version 2: the header (code, version), Dimension (code, position, 2), Vertices (code, position,
  // count, then x y as 8-byte reals and a 4-byte ref per vertex), Triangles (code, position, count,
  // 4 words), End (code, position).
  const std::string le = medit_mesh_text(f, MeditEncoding::binary, 2);
  std::vector<int> w{4, 4, 4, 4, 4, 4, 4, 4};
  for (int i = 0; i < 3; ++i) w.insert(w.end(), {8, 8, 4});
  w.insert(w.end(), {4, 4, 4, 4, 4, 4, 4, 4, 4});
  const MeshFile back = read_medit(swapped(le, w), "big-endian.meshb");
  expect_same(back, f);
  // Version 4 .solb: 8-byte positions, counts and reals; the type words stay 4 bytes.
  const std::vector<Sym2<Rational>> metrics{{2, Rational(1, 8), 3}};
  const std::string sol = medit_sol_text(metrics, MeditEncoding::binary, 4);
  const std::vector<int> sw{4, 4, 4, 8, 4, 4, 8, 8, 4, 4, 8, 8, 8, 4, 8};
  expect_same_metrics(read_medit_sol(swapped(sol, sw), "big-endian.solb"), metrics);
}

TEST(Medit, SizesAndTensors) {
  // Type 1: a size h, the metric I/h² exactly (h = 0.1 gives 100, not the double's square).
  const auto sizes = read_medit_sol("MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n2\n1 1\n0.1\n4\nEnd\n", "h.sol");
  expect_same_metrics(sizes, {{100, 0, 100}, {Rational(1, 16), 0, Rational(1, 16)}});
  // Type 3 in 2D: m11 m12 m22.
  const auto tensors = read_medit_sol("MeshVersionFormatted 2\nDimension 2\nSolAtVertices 1 1 3 4 1 0.5 End", "t.sol");
  expect_same_metrics(tensors, {{4, 1, Rational(1, 2)}});
}

TEST(Medit, PlanarThreeDimensionalOnlyWhenAllowed) {
  const char* text = "MeshVersionFormatted 2 Dimension 3 Vertices 3 0 0 0 1 1 0 0 2 0 1 0 3 Triangles 1 1 2 3 0 End";
  EXPECT_NE(error_of([&] { read_medit(text, "p.mesh"); })
                .find("p.mesh:1: Dimension 3 with every z = 0 and no Tetrahedra: a planar mesh in 3D is read only when allowed (--planar-3d)"),
            std::string::npos)
      << error_of([&] { read_medit(text, "p.mesh"); });
  const MeshFile f = read_medit(text, "p.mesh", {true});
  EXPECT_EQ(f.dimension, 2);
  EXPECT_EQ(f.mesh.sites[1].x, 1);
  const char* lifted = "MeshVersionFormatted 2 Dimension 3 Vertices 1 0 0 0.5 1 End";
  EXPECT_NE(error_of([&] { read_medit(lifted, "z.mesh", {true}); }).find("vertex 1 has z != 0: a surface mesh, neither planar nor tetrahedral"),
            std::string::npos);
}

// A tetrahedral mesh (issue 39): Dimension 3 with Tetrahedra, its Triangles the declared boundary,
// every number exact; its .sol of Dimension 3 in Medit's order m11 m12 m22 m13 m23 m33 (the lower
// triangle by rows: the second entry is m12, the fourth m13); written back and read again the same,
// in text and binary. Prisms and hexahedra are refused by name.
TEST(Medit, TetrahedralMeshesAndTheirMetrics) {
  const char* text =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 0.125 2\n"
      "Triangles\n1\n1 3 2 7\nTetrahedra\n1\n1 2 3 4 5\nEnd\n";
  const MeshFile f = read_medit(text, "t.mesh");
  ASSERT_EQ(f.dimension, 3);
  ASSERT_EQ(f.mesh3.vertices.size(), 4u);
  EXPECT_EQ(f.mesh3.vertices[3].z, Rational(1, 8));
  EXPECT_EQ(f.mesh3.tetrahedra, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}}));
  EXPECT_EQ(f.mesh3.triangles, (std::vector<std::array<int, 3>>{{0, 2, 1}}));
  EXPECT_EQ(f.tetrahedron_refs, std::vector<int>{5});
  EXPECT_TRUE(f.mesh.sites.empty() && f.mesh.triangles.empty());
  const auto sol = read_medit_sol3("MeshVersionFormatted 2 Dimension 3 SolAtVertices 2 1 3 4 1 3 0.5 0.25 2 1 0 1 0 0 1 End", "t.sol");
  ASSERT_EQ(sol.size(), 2u);
  EXPECT_EQ(sol[0], (anisocert::predicates::Sym3<Rational>{4, 1, Rational(1, 2), 3, Rational(1, 4), 2}));
  const auto sizes = read_medit_sol3("MeshVersionFormatted 2 Dimension 3 SolAtVertices 1 1 1 0.5 End", "h.sol");
  EXPECT_EQ(sizes[0], (anisocert::predicates::Sym3<Rational>{4, 0, 0, 4, 0, 4}));
  // diag(−1, −1, 1) has determinant 1 and is not positive definite (Sylvester's criterion).
  EXPECT_NE(error_of([] { read_medit_sol3("MeshVersionFormatted 2 Dimension 3 SolAtVertices 1 1 3 -1 0 -1 0 0 1 End", "n.sol"); })
                .find("n.sol:1: in SolAtVertices: vertex 1: the metric [-1 0 -1 0 0 1] is not positive definite"),
            std::string::npos);
  EXPECT_NE(error_of([] { read_medit_sol("MeshVersionFormatted 2 Dimension 3 SolAtVertices 1 1 1 0.5 End", "d.sol"); })
                .find("a metric of Dimension 3 is not a 2D metric"),
            std::string::npos);
  MeshFile g = f;
  g.mesh3.metrics = {{4, 1, Rational(1, 2), 3, Rational(1, 4), 2}, {1, 0, 0, 1, 0, 1}, {1, 0, 0, 1, 0, 1}, {2, 0, 0, 2, 0, 2}};
  for (const auto e : {MeditEncoding::ascii, MeditEncoding::binary}) {
    const MeshFile back = read_medit(medit_mesh_text(g, e), "back");
    EXPECT_EQ(back.dimension, 3);
    EXPECT_EQ(back.mesh3.tetrahedra, g.mesh3.tetrahedra);
    EXPECT_EQ(back.mesh3.triangles, g.mesh3.triangles);
    EXPECT_EQ(back.mesh3.vertices[3].z, Rational(1, 8));
    EXPECT_EQ(read_medit_sol3(medit_sol_text(g.mesh3.metrics, e), "back.sol"), g.mesh3.metrics);
  }
  EXPECT_NE(error_of([] { read_medit("MeshVersionFormatted 2 Dimension 3 Vertices 1 0 0 0 1 Prisms 1 1 1 1 1 1 1 0 End", "p.mesh"); })
                .find("the mesh has prisms: anisocert certifies meshes of triangles or tetrahedra only"),
            std::string::npos);
  EXPECT_NE(error_of([] { read_medit("MeshVersionFormatted 2 Dimension 2 Vertices 1 0 0 1 Tetrahedra 1 1 1 1 1 0 End", "t2.mesh"); })
                .find("Tetrahedra in a mesh of Dimension 2"),
            std::string::npos);
}

TEST(Medit, MalformedFilesNameTheFileTheLineAndTheKeyword) {
  const std::pair<const char*, const char*> cases[] = {
      {"MeshVersionFormatted 5\nDimension 2\n", "bad.mesh:1: the version after MeshVersionFormatted is 5, outside [1, 4]"},
      {"MeshVersionFormatted 2\nDimension 2\nVertices\n2\n0 0 1\n", "bad.mesh:5: in Vertices: the file ends where x was expected"},
      {"MeshVersionFormatted 2\nDimension 2\nVertices\n1\n0 0 1\nTriangles\n1\n1 2 1 0\n", "bad.mesh:8: in Triangles: a triangle's vertex 2 is not a vertex (1..1)"},
      {"MeshVersionFormatted 2\nDimension 2\nVertices\n1\nnan 0 1\n", "bad.mesh:5: in Vertices: x: \"nan\""},
      {"MeshVersionFormatted 2\nVertices\n1\n0 0 1\n", "bad.mesh:2: in Vertices: Vertices before Dimension"},
      {"MeshVersionFormatted 2\nDimension\n", "bad.mesh:2: in Dimension: the file ends where the dimension was expected"},
      {"MeshVersionFormatted 2\nDimension 2\nVertices 99999999999\n", "count 99999999999 exceeds what the file can hold"},
      {"MeshVersionFormatted 2\nDimension 2\nCorners 1 1\n", "in Corners: a corner 1 is not a vertex (1..0)"},
  };
  for (const auto& c : cases) {
    const char *text = c.first, *message = c.second;  // named copies: clang 14 lambdas cannot capture bindings
    EXPECT_NE(error_of([&] { read_medit(text, "bad.mesh"); }).find(message), std::string::npos)
        << text << "\n got: " << error_of([&] { read_medit(text, "bad.mesh"); });
  }
  const std::pair<const char*, const char*> sols[] = {
      {"MeshVersionFormatted 2 Dimension 2 SolAtVertices 1 1 3 1 2 1 End", "vertex 1: the metric [1 2 1] is not positive definite"},
      {"MeshVersionFormatted 2 Dimension 2 SolAtVertices 1 1 1 -2 End", "vertex 1: the size -2 is not positive"},
      {"MeshVersionFormatted 2 Dimension 2 SolAtVertices 1 1 2 1 1 End", "solution type 2 is neither 1"},
      {"MeshVersionFormatted 2 Dimension 2 SolAtVertices 1 2 1 1 1 1 End", "2 solutions per vertex"},
      {"MeshVersionFormatted 2 Dimension 2 SolAtVertices 2 1 3 1 0 1", "in SolAtVertices: the file ends where m11 was expected"},
      {"MeshVersionFormatted 2 Dimension 2 End", "no SolAtVertices"},
  };
  for (const auto& c : sols) {
    const char *text = c.first, *message = c.second;
    EXPECT_NE(error_of([&] { read_medit_sol(text, "bad.sol"); }).find(message), std::string::npos)
        << text << "\n got: " << error_of([&] { read_medit_sol(text, "bad.sol"); });
  }
}

TEST(Medit, BinaryTruncationsAndBadPositionsNameTheByte) {
  const MeshFile f = square(true);
  const std::string full = medit_mesh_text(f, MeditEncoding::binary, 2);
  // Cut anywhere inside: never a crash, always the file and a byte offset.
  for (std::size_t cut = 1; cut < full.size(); cut += 3) {
    const std::string e = error_of([&] { read_medit(full.substr(0, cut), "cut.meshb"); });
    if (cut < 8 || e.empty()) continue;  // a cut right after a keyword may leave a readable file
    EXPECT_EQ(e.rfind("cut.meshb: byte ", 0), 0u) << cut << ": " << e;
  }
  // A next-keyword position past the end of the file.
  std::string bad = full;
  const std::int32_t huge = 1 << 30;
  std::memcpy(bad.data() + 12, &huge, 4);  // Dimension's next-keyword position
  EXPECT_NE(error_of([&] { read_medit(bad, "pos.meshb"); }).find("past the end of the file"), std::string::npos);
}

}  // namespace
