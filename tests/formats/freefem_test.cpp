// FreeFem++'s .msh and BAMG's .mtr (io/formats/freefem.hpp): hand-written files of known content,
// files made by FreeFem++ and bamg (tests/formats/peers/freefem, see its README), the writer's
// files read back exactly, malformed files refused with the file, the line and the section named,
// and the catalogue's freefem-* and bamg-* cases failing in the readers with their messages.
#include "io/formats/freefem.hpp"

#include "format_test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace {

using anisocert::test_support::error_of;

using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::predicates::Sym2;
using namespace anisocert::io;
namespace fs = std::filesystem;

Rational q(const char* text) { return parse_rational(text); }

const fs::path peers = fs::path(ANISOCERT_MALFORMED_DIR "/../peers/freefem");


void expect_metric(const Sym2<Rational>& m, const Rational& m11, const Rational& m12, const Rational& m22) {
  EXPECT_EQ(m.m11, m11);
  EXPECT_EQ(m.m12, m12);
  EXPECT_EQ(m.m22, m22);
}

// A unit square and an off-grid centre: labels on vertices (one negative), triangles and edges.
constexpr const char* square = R"(5 4 4
0 0 1
1 0 2
1 1 -3
0 1 4
0.1 -2.5e-3 0
1 2 5 7
2 3 5 7
3 4 5 8
4 1 5 8
1 2 11
2 3 12
3 4 13
4 1 14
)";

TEST(FreeFem, ReadsAHandWrittenMeshNumberedFromOne) {
  const MeshFile f = read_freefem(square, "square.msh");
  ASSERT_EQ(f.mesh.sites.size(), 5u);
  EXPECT_EQ(f.mesh.sites[1].x, 1);
  EXPECT_EQ(f.mesh.sites[1].y, 0);
  EXPECT_EQ(f.mesh.sites[4].x, Rational(1, 10));
  EXPECT_EQ(f.mesh.sites[4].y, Rational(-1, 400));
  EXPECT_EQ(f.vertex_refs, (std::vector<int>{1, 2, -3, 4, 0}));
  EXPECT_EQ(f.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}));
  EXPECT_EQ(f.triangle_refs, (std::vector<int>{7, 7, 8, 8}));
  EXPECT_EQ(f.mesh.edges, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
  EXPECT_EQ(f.edge_refs, (std::vector<int>{11, 12, 13, 14}));
  EXPECT_TRUE(f.mesh.metrics.empty());
}

TEST(FreeFem, LooksLikeFreeFemOnlyWhenThreeNonNegativeIntegersLead) {
  EXPECT_TRUE(looks_like_freefem("44 60 28\n1 0 2\n"));
  EXPECT_TRUE(looks_like_freefem("  0 0 0"));
  EXPECT_TRUE(looks_like_freefem("4\r\n2\r\n4\r\n"));
  EXPECT_FALSE(looks_like_freefem("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"));
  EXPECT_FALSE(looks_like_freefem("$NOD\n3\n"));
  EXPECT_FALSE(looks_like_freefem("4 2\n"));
  EXPECT_FALSE(looks_like_freefem("4 -2 4\n"));
  EXPECT_FALSE(looks_like_freefem("4 2.0 4\n"));
  EXPECT_FALSE(looks_like_freefem(""));
}

TEST(FreeFem, ReadsTheMeshesFreeFemAndBamgMade) {
  // square_hole.msh (FreeFem++ savemesh): "44 60 28"; vertex 1 "1 0 2", vertex 4
  // "0.715481319153 0.191113966369 0"; triangle 1 "16 9 14 0"; edges "15 8 5" ... "2 1 1".
  const MeshFile f = read_freefem_file((peers / "square_hole.msh").string());
  EXPECT_EQ(f.mesh.sites.size(), 44u);
  EXPECT_EQ(f.mesh.triangles.size(), 60u);
  ASSERT_EQ(f.mesh.edges.size(), 28u);
  EXPECT_EQ(f.mesh.sites[0].x, 1);
  EXPECT_EQ(f.vertex_refs[0], 2);
  EXPECT_EQ(f.mesh.sites[3].x, q("0.715481319153"));
  EXPECT_EQ(f.mesh.sites[3].y, q("0.191113966369"));
  EXPECT_EQ(f.vertex_refs[3], 0);
  EXPECT_EQ(f.mesh.triangles[0], (std::array<int, 3>{15, 8, 13}));
  EXPECT_EQ(f.mesh.edges.front(), (std::pair<int, int>{14, 7}));
  EXPECT_EQ(f.edge_refs.front(), 5);
  EXPECT_EQ(f.mesh.edges.back(), (std::pair<int, int>{1, 0}));
  EXPECT_EQ(f.edge_refs.back(), 1);

  // adapted.msh (FreeFem++ adaptmesh): "76 115 37"; vertex 2 "0.761132523585 0 1"; triangle 1
  // "1 4 3 0"; the last edge "2 1 1".
  const MeshFile a = read_freefem_file((peers / "adapted.msh").string());
  EXPECT_EQ(a.mesh.sites.size(), 76u);
  EXPECT_EQ(a.mesh.triangles.size(), 115u);
  EXPECT_EQ(a.mesh.edges.size(), 37u);
  EXPECT_EQ(a.mesh.sites[1].x, q("0.761132523585"));
  EXPECT_EQ(a.vertex_refs[1], 1);
  EXPECT_EQ(a.mesh.triangles[0], (std::array<int, 3>{0, 3, 2}));
  EXPECT_EQ(a.mesh.edges.back(), (std::pair<int, int>{1, 0}));

  // bamg_adapted.msh (bamg -omsh): "53 75 31"; vertex 1 "1 0 34"; triangle 1 "1 7 4 0"; the last
  // edge "31 1 1".
  const MeshFile b = read_freefem_file((peers / "bamg_adapted.msh").string());
  EXPECT_EQ(b.mesh.sites.size(), 53u);
  EXPECT_EQ(b.mesh.triangles.size(), 75u);
  EXPECT_EQ(b.mesh.edges.size(), 31u);
  EXPECT_EQ(b.vertex_refs[0], 34);
  EXPECT_EQ(b.mesh.triangles[0], (std::array<int, 3>{0, 6, 3}));
  EXPECT_EQ(b.mesh.edges.back(), (std::pair<int, int>{30, 0}));
}

TEST(FreeFem, RefusesMalformedMeshesNamingTheLineAndTheSection) {
  const std::vector<std::pair<const char*, const char*>> cases{
      {"3 1 0\n0 0 1\n1 0 1\n0 1 1\n0 1 2 0\n", "m.msh:5: triangle 1: vertex 0 is out of range (vertices 1..3)"},
      {"3 1 0\n0 0 1\n1 0 1\n0 1 1\n1 2 4 0\n", "m.msh:5: triangle 1: vertex 4 is out of range (vertices 1..3)"},
      {"3 0 1\n0 0 1\n1 0 1\n0 1 1\n1 -1 1\n", "m.msh:5: boundary edge 1: vertex -1 is out of range"},
      {"3 1 0\n0 0 1\n1 0 1\n", "the file ends where vertex 3: x was expected"},
      {"3 1 0\n0 0 1\n1 0 1\n0 1 1\n1 2 3", "m.msh:5: the file ends where triangle 1: label was expected"},
      {"3 0 0\n0 0 1\n1 0 1\n0 1 1\n0 0 1\n", "m.msh:5: boundary edges: more data than the header declares (0): \"0\""},
      {"3 0 0\n0 0 1\nNaN 0 1\n0 1 1\n", "m.msh:3: vertex 2: x: \"NaN\" is not an exact number"},
      {"3 0 0\n0 0 1\n1 0 1\n0 Infinity 1\n", "m.msh:4: vertex 3: y: \"Infinity\" is not an exact number"},
      {"3 0 0\n0 0 1\n1 0 1.5\n", "m.msh:3: vertex 2: label: \"1.5\" is not an integer"},
      {"-3 0 0\n", "m.msh:1: header: number of vertices (nv) is -3"},
      {"3 0 99999999999\n", "m.msh:1: header: number of boundary edges (nbe) is 99999999999, outside"},
      {"3 x 0\n", "m.msh:1: header: number of triangles (nt): \"x\" is not an integer"},
  };
  for (const auto& [text, message] : cases) {
    const std::string error = error_of([&, text = text] { read_freefem(text, "m.msh"); });
    EXPECT_NE(error.find(message), std::string::npos) << "expected \"" << message << "\", got \"" << error << "\"";
  }
}

TEST(FreeFem, WritesAMeshAndItsMetricsThatReadBackExactly) {
  MeshFile m = read_freefem(square, "square.msh");
  m.mesh.sites[2] = {q("12345678901234567890.125"), q("-7.5e-12")};
  m.mesh.metrics = {{4, -1, 3}, {q("0.1"), 0, q("0.2")}, {1, 0, 1}, {100, q("99.5"), 100}, {2, 1, 1}};
  const fs::path dir = anisocert::test_support::fresh_dir("freefem_test_round_trip");
  const std::vector<FileText> files = write_freefem_file(m, (dir / "rt.msh").string());
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].path, (dir / "rt.msh").string());
  EXPECT_EQ(files[1].path, (dir / "rt.mtr").string());
  EXPECT_EQ(files[1].content.substr(0, 14), "5 3\n4 -1 3\n0.1");
  for (const FileText& f : files) std::ofstream(f.path, std::ios::binary) << f.content;
  MeshFile r = read_freefem_file(files[0].path);
  attach_metrics(r, read_bamg_metric_file(files[1].path), files[1].path);
  ASSERT_EQ(r.mesh.sites.size(), m.mesh.sites.size());
  for (std::size_t i = 0; i < m.mesh.sites.size(); ++i) {
    EXPECT_EQ(r.mesh.sites[i].x, m.mesh.sites[i].x) << "vertex " << i;
    EXPECT_EQ(r.mesh.sites[i].y, m.mesh.sites[i].y) << "vertex " << i;
    expect_metric(r.mesh.metrics[i], m.mesh.metrics[i].m11, m.mesh.metrics[i].m12, m.mesh.metrics[i].m22);
  }
  EXPECT_EQ(r.mesh.triangles, m.mesh.triangles);
  EXPECT_EQ(r.mesh.edges, m.mesh.edges);
  EXPECT_EQ(r.vertex_refs, m.vertex_refs);
  EXPECT_EQ(r.triangle_refs, m.triangle_refs);
  EXPECT_EQ(r.edge_refs, m.edge_refs);
}

TEST(FreeFem, WritesOneFileWithoutMetricsAndRefusesANumberWithNoFiniteDecimal) {
  MeshFile m;
  m.mesh.sites = {{0, 0}, {1, 0}, {0, 1}};
  m.mesh.triangles = {{0, 1, 2}};
  const std::vector<FileText> files = write_freefem_file(m, "plain.msh");
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].content, "3 1 0\n0 0 0\n1 0 0\n0 1 0\n1 2 3 0\n");
  m.mesh.sites[2].y = Rational(1, 3);
  EXPECT_NE(error_of([&] { write_freefem_file(m, "t.msh"); }).find("t.msh: vertex 3: y = 1/3 has no finite decimal"),
            std::string::npos);
}

// Each catalogue case (tests/formats/malformed/freefem-* and bamg-*) fails in the readers, as the
// registry chains them (the mesh, then the metric file and attach_metrics), with its message and
// the file case.json names.
TEST(FreeFem, CatalogueCasesFailInTheReadersWithTheirMessages) {
  int cases = 0;
  for (const auto& d : fs::directory_iterator(ANISOCERT_MALFORMED_DIR)) {
    const std::string name = d.path().filename().string();
    if (name.rfind("freefem-", 0) != 0 && name.rfind("bamg-", 0) != 0) continue;
    ++cases;
    const nlohmann::json c = nlohmann::json::parse(std::ifstream(d.path() / "case.json"));
    const std::string named = c.value("metric", c["mesh"].get<std::string>());
    const std::string error = error_of([&] {
      MeshFile f = read_freefem_file((d.path() / c["mesh"].get<std::string>()).string());
      if (!c.contains("metric")) return;
      const std::string metric = (d.path() / named).string();
      attach_metrics(f, read_bamg_metric_file(metric), metric);
    });
    EXPECT_NE(error.find(c["message"].get<std::string>()), std::string::npos) << name << ": " << error;
    EXPECT_NE(error.find(named), std::string::npos) << name << ": " << error;
  }
  EXPECT_GE(cases, 12);
}

TEST(Bamg, ASizeGivesTheIdentityOverHSquared) {
  const auto metrics = read_bamg_metric("3 1\n0.5\n0.1\n2\n", "s.mtr");
  ASSERT_EQ(metrics.size(), 3u);
  expect_metric(metrics[0], 4, 0, 4);
  expect_metric(metrics[1], 100, 0, 100);  // exact: 1/0.1² is 100, not 99.99...
  expect_metric(metrics[2], Rational(1, 4), 0, Rational(1, 4));
}

TEST(Bamg, ATensorIsReadAsA11A21A22) {
  const auto metrics = read_bamg_metric("2 3\n4 -1 3\n0.1 0 0.2\n", "t.mtr");
  ASSERT_EQ(metrics.size(), 2u);
  expect_metric(metrics[0], 4, -1, 3);
  expect_metric(metrics[1], Rational(1, 10), 0, Rational(1, 5));
}

TEST(Bamg, RefusesWhatIsNotAMetricAndCountsThatDoNotMatch) {
  const std::vector<std::pair<const char*, const char*>> cases{
      {"2 3\n1 0 1\n1 2 1\n", "m.mtr:3: vertex 2: metric a11 a21 a22 = 1 2 1 is not positive definite"},
      {"1 3\n1 1 1\n", "m.mtr:2: vertex 1: metric a11 a21 a22 = 1 1 1 is not positive definite"},  // singular
      {"1 3\n-1 0 -1\n", "vertex 1: metric a11 a21 a22 = -1 0 -1 is not positive definite"},       // det > 0
      {"2 1\n0.5\n0\n", "m.mtr:3: vertex 2: size h = 0 is not positive"},
      {"2 1\n0.5\n-0.25\n", "m.mtr:3: vertex 2: size h = -0.25 is not positive"},
      {"2 1\n0.5\n", "the file ends where vertex 2: size h was expected"},
      {"2 3\n1 0 1\n1 0", "m.mtr:3: the file ends where vertex 2: a22 was expected"},
      {"2 1\n0.5\n0.5\n0.5\n", "m.mtr:4: metrics: more data than the header declares (2): \"0.5\""},
      {"1 1\nnan\n", "m.mtr:2: vertex 1: size h: \"nan\" is not an exact number"},
      {"1 3\n1 0 inf\n", "m.mtr:2: vertex 1: a22: \"inf\" is not an exact number"},
      {"2 2\n1 1\n1 1\n", "m.mtr:1: header: 2 values per vertex, where BAMG has 1 (a size h) or 3 (a11 a21 a22)"},
      {"-2 1\n", "m.mtr:1: header: number of vertices (nbv) is -2"},
      // The header's kind against the first vertex's line: BAMG reads a stream of numbers, so only
      // the failure says so (the tensors read as sizes: 1, 0 is the second).
      {"2 1\n1 0 1\n1 0 1\n", "m.mtr:2: vertex 2: size h = 0 is not positive (the metric is I/h²) (line 2 holds 3 values, "
                               "where the header declares 1 per vertex: should its second number be 3?)"},
      {"\n2 3\n\n0.5\n0.5\n", "(line 4 holds 1 value, where the header declares 3 per vertex: should its second number be 1?)"},
      // A header over two lines, or sharing its line with values: the line of the first value.
      {"2\n1\n1 0 1\n1 0 1\n", "(line 3 holds 3 values, where the header declares 1 per vertex: should its second number be 3?)"},
      {"2 3 0.5\n0.5\n", "(line 1 holds 1 value, where the header declares 3 per vertex: should its second number be 1?)"},
      // A short line further on: the failure comes lines later, from values shifted across lines.
      {"3 3\n1 0 1\n1 0\n1 0 1\n", "m.mtr:4: the file ends where vertex 3: a22 was expected"},
      {"3 3\n1 0 1\n1 0\n1 0 1\n", "(line 3 holds 2 values, where the header declares 3 per vertex: the vertices after it are read shifted)"},
  };
  for (const auto& [text, message] : cases) {
    const std::string error = error_of([&, text = text] { read_bamg_metric(text, "m.mtr"); });
    EXPECT_NE(error.find(message), std::string::npos) << "expected \"" << message << "\", got \"" << error << "\"";
  }
  MeshFile f = read_freefem(square, "square.msh");
  EXPECT_EQ(error_of([&] { attach_metrics(f, read_bamg_metric("4 1\n1\n1\n1\n1\n", "m.mtr"), "m.mtr"); }),
            "m.mtr: 4 metrics for a mesh of 5 vertices");
}

TEST(Bamg, ReadsTheMetricsBamgWrote) {
  MeshFile f = read_freefem_file((peers / "square_hole.msh").string());
  // square_hole.mtr (bamg -oM): "44 3", then "16.678 6.06545 5.2332" ... "1730.81 -39.5967 85.9333".
  const auto tensors = read_bamg_metric_file((peers / "square_hole.mtr").string());
  ASSERT_EQ(tensors.size(), 44u);
  expect_metric(tensors.front(), q("16.678"), q("6.06545"), q("5.2332"));
  expect_metric(tensors.back(), q("1730.81"), q("-39.5967"), q("85.9333"));
  attach_metrics(f, tensors, "square_hole.mtr");
  EXPECT_EQ(f.mesh.metrics.size(), 44u);
  // square_hole_iso.mtr (bamg -oM -iso): "44 1", then "0.227659" ... "0.0240301".
  const auto sizes = read_bamg_metric_file((peers / "square_hole_iso.mtr").string());
  ASSERT_EQ(sizes.size(), 44u);
  const Rational h = q("0.227659");
  expect_metric(sizes.front(), 1 / (h * h), 0, 1 / (h * h));
  expect_metric(sizes.back(), 1 / (q("0.0240301") * q("0.0240301")), 0, 1 / (q("0.0240301") * q("0.0240301")));
}

TEST(Bamg, WritesTensorsReadBackExactlyAndRefusesANumberWithNoFiniteDecimal) {
  const std::vector<Sym2<Rational>> metrics{{4, -1, 3}, {q("0.1"), q("-0.05"), q("0.125")}, {q("1e-9"), 0, 1}};
  const FileText file = write_bamg_metric(metrics, "w.mtr");
  EXPECT_EQ(file.path, "w.mtr");
  EXPECT_EQ(file.content, "3 3\n4 -1 3\n0.1 -0.05 0.125\n0.000000001 0 1\n");
  const auto back = read_bamg_metric(file.content, file.path);
  ASSERT_EQ(back.size(), 3u);
  expect_metric(back[1], Rational(1, 10), Rational(-1, 20), Rational(1, 8));
  expect_metric(back[2], Rational(1, 1000000000), 0, 1);
  EXPECT_NE(error_of([&] { write_bamg_metric({{Rational(1, 3), 0, 1}}, "w.mtr"); })
                .find("w.mtr: metric 1: a11 = 1/3 has no finite decimal"),
            std::string::npos);
}

}  // namespace
