// The project's mesh file (io/mesh_json.hpp; DESIGN.md § Command line and files): exact numbers from JSON text,
// the default box, exact validation of the domain polygon and of the sites, and error messages
// that name the file and the offending index. Expected values are worked out by hand.

#include "io/mesh_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using anisocert::Integer;
using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::io::InputError;
using anisocert::io::read_mesh_json;
using anisocert::io::read_mesh_json_file;
using Mesh = anisocert::geometry::Mesh<Rational>;
using Point = anisocert::predicates::Point2<Rational>;

namespace {

Mesh read(const std::string& text) {
  std::istringstream in(text);
  return read_mesh_json(in, "t.json");
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

#define EXPECT_ERROR(text, expected) EXPECT_NE(error_of(text).find(expected), std::string::npos) << error_of(text)

Point P(const char* x, const char* y) { return {parse_rational(x), parse_rational(y)}; }

void expect_polygon(const std::vector<Point>& got, const std::vector<Point>& expected) {
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].x, expected[k].x) << "vertex " << k;
    EXPECT_EQ(got[k].y, expected[k].y) << "vertex " << k;
  }
}

// A document with unit metrics at the given sites and the given domain.
std::string with_domain(const std::vector<std::string>& sites, const std::string& domain) {
  std::string s = R"({"sites": [)";
  for (std::size_t i = 0; i < sites.size(); ++i)
    s += (i ? ", " : "") + std::string(R"({"x": )") + sites[i].substr(0, sites[i].find(' ')) + R"(, "y": )" +
         sites[i].substr(sites[i].find(' ') + 1) + R"(, "metric": [1, 0, 1]})";
  return s + "]" + (domain.empty() ? "" : R"(, "domain": )" + domain) + "}";
}

const std::string L_shape = R"([[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]])";  // reflex corner (1, 1)

}  // namespace

TEST(SiteSet, PlainJsonNumbersAreExactFromTheirText) {
  const Mesh s = read(R"({"sites": [
      {"x": 0.1, "y": 123456789012345678901234567890, "metric": [4, 0.1, 1]},
      {"x": "1/3", "y": -2, "metric": ["4", "0", "1.25e-3"]},
      {"x": 1.25e-3, "y": -0.5E1, "metric": [1, 0, 1]}]})");
  ASSERT_EQ(s.sites.size(), 3u);
  EXPECT_EQ(s.sites[0].x, Rational(1) / 10);  // not the double nearest 0.1
  EXPECT_EQ(s.sites[0].y, Rational(Integer("123456789012345678901234567890")));
  EXPECT_EQ(s.metrics[0].m12, Rational(1) / 10);
  EXPECT_EQ(s.sites[1].x, Rational(1, 3));
  EXPECT_EQ(s.sites[1].y, Rational(-2));
  EXPECT_EQ(s.metrics[1].m22, Rational(1, 800));
  EXPECT_EQ(s.sites[2].x, Rational(1, 800));
  EXPECT_EQ(s.sites[2].y, Rational(-5));
  EXPECT_TRUE(s.segments.empty());
}

TEST(SiteSet, MalformedJsonNamesTheBytePosition) {
  EXPECT_ERROR(R"({"sites": [})", "t.json: invalid JSON at byte ");
  EXPECT_ERROR(R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1]}]} x)", "t.json: invalid JSON at byte ");
  EXPECT_ERROR("", "t.json: invalid JSON at byte ");
  // Beyond double range: the JSON parser refuses it; a string holds any exact number.
  EXPECT_ERROR(R"({"sites": [{"x": 1e400, "y": 0, "metric": [1, 0, 1]}]})", "t.json: invalid JSON at byte ");
  EXPECT_EQ(read(R"({"sites": [{"x": "1e320", "y": 0, "metric": [1, 0, 1]}]})").sites[0].x,
            Rational(boost::multiprecision::pow(Integer(10), 320)));
}

TEST(SiteSet, NumbersBeyondTheMagnitudeLimitAreRefusedByName) {
  // Past 2^±1100 (numbers/rational.hpp), as the text formats refuse them: 1e-1000 made anisocert
  // diagram run for seconds, 1e-5000 without end.
  EXPECT_ERROR(R"({"sites": [{"x": "1e400", "y": 0, "metric": [1, 0, 1]}]})",
               "t.json: sites[0].x: \"1e400\" is outside the magnitudes anisocert reads");
  EXPECT_ERROR(R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, "1e-1000"]}]})",
               "t.json: sites[0].metric[2]: \"1e-1000\" is outside the magnitudes anisocert reads");
  EXPECT_ERROR(R"({"sites": [{"x": 1e-400, "y": 0, "metric": [1, 0, 1]}]})",  // a plain JSON number too
               "t.json: sites[0].x: \"1e-400\" is outside the magnitudes anisocert reads");
  EXPECT_ERROR(R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1]}], "domain": [[0, 0], ["1e-2000", 0], [0, 1]]})",
               "t.json: domain[1][0]: \"1e-2000\" is outside the magnitudes anisocert reads");
  EXPECT_EQ(read(R"({"sites": [{"x": "1e-330", "y": 0, "metric": [1, 0, 1]}]})").sites[0].x, parse_rational("1e-330"));
}

TEST(SiteSet, MessagesQuoteOneShortLine) {
  // A newline in a number, a long key, a long number: the message stays one short line.
  const std::string long_key(5000, 'k');
  const std::string long_number = "0." + std::string(5000, '3');
  for (const std::string& doc :
       {std::string(R"({"sites": [{"x": "1\nanisocert: forged", "y": 0, "metric": [1, 0, 1]}]})"),
        R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1], ")" + long_key + R"(": 1}]})",
        R"({")" + long_key + R"(": 1, ")" + long_key + R"(": 2})",
        R"({"sites": [{"x": ")" + long_number + R"(", "y": 0, "metric": [1, 0, 1]}, {"x": ")" + long_number +
            R"(", "y": 0, "metric": [1, 0, 1]}]})",
        R"({"sites": [{"x": ")" + long_number + R"(", "y": 0, "metric": [1, 0, 1]}], "domain": [[1, 0], [2, 0], [1, 1]]})",
        R"({"sites": [{"x": ")" + long_number + R"()" + "\n" + R"(", "y": 0, "metric": [1, 0, 1]}]})"}) {
    try {
      read(doc);
      ADD_FAILURE() << doc.substr(0, 80);
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_LT(m.size(), 250u) << m;
    }
  }
  EXPECT_ERROR(R"({"sites": [{"x": "1\nanisocert: forged", "y": 0, "metric": [1, 0, 1]}]})",
               "t.json: sites[0].x: \"1\\x0aanisocert: forged\" is not an exact number");
  EXPECT_ERROR(R"({"sites": [{"x": ")" + long_number + R"(", "y": 0, "metric": [1, 0, 1]}, {"x": ")" + long_number +
                   R"(", "y": 0, "metric": [1, 0, 1]}]})",
               "t.json: sites[0] and sites[1] coincide at (≈3.333333333e-01, 0)");
}

TEST(SiteSet, TopLevelErrors) {
  EXPECT_ERROR("[1, 2]", "t.json: the top level must be an object, got [1,2]");
  EXPECT_ERROR("{}", "t.json: missing key \"sites\"");
  EXPECT_ERROR(R"({"sites": []})", "t.json: sites: expected a non-empty array of sites");
  EXPECT_ERROR(R"({"sites": {}})", "t.json: sites: expected a non-empty array of sites");
  EXPECT_ERROR(R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1]}], "domian": []})",
               "t.json: unknown key \"domian\" (expected sites, domain, segments, edges, triangles)");
  EXPECT_ERROR(R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1]}], "sites": []})",
               "t.json: key \"sites\" appears twice");
}

TEST(SiteSet, SiteErrorsNameTheSiteAndField) {
  const std::string ok = R"({"x": 0, "y": 0, "metric": [1, 0, 1]})";
  const auto doc = [&](const std::string& second) { return R"({"sites": [)" + ok + ", " + second + "]}"; };
  EXPECT_ERROR(doc("[0, 0]"), "t.json: sites[1]: expected an object");
  EXPECT_ERROR(doc(R"({"x": 1, "y": 0, "metrc": [1, 0, 1]})"),
               "t.json: sites[1]: unknown key \"metrc\" (expected x, y, metric)");
  EXPECT_ERROR(doc(R"({"x": 1, "metric": [1, 0, 1]})"), "t.json: sites[1]: missing key \"y\"");
  EXPECT_ERROR(doc(R"({"x": 1, "x": 2, "y": 0, "metric": [1, 0, 1]})"), "t.json: sites[1]: key \"x\" appears twice");
  EXPECT_ERROR(doc(R"({"x": "abc", "y": 0, "metric": [1, 0, 1]})"), "t.json: sites[1].x: \"abc\" is not an exact number");
  EXPECT_ERROR(doc(R"({"x": "1/0", "y": 0, "metric": [1, 0, 1]})"), "t.json: sites[1].x: \"1/0\" is not an exact number");
  EXPECT_ERROR(doc(R"({"x": 1, "y": true, "metric": [1, 0, 1]})"), "t.json: sites[1].y: expected a number");
  EXPECT_ERROR(doc(R"({"x": 1, "y": 0, "metric": [1, 0]})"), "t.json: sites[1].metric: expected [m11, m12, m22]");
  EXPECT_ERROR(doc(R"({"x": 1, "y": 0, "metric": [1, 0, null]})"), "t.json: sites[1].metric[2]: expected a number");
}

TEST(SiteSet, MetricMustBePositiveDefiniteExactly) {
  const auto doc = [](const std::string& metric) {
    return R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1]}, {"x": 1, "y": 0, "metric": )" + metric + "}]}";
  };
  EXPECT_ERROR(doc("[1, 2, 1]"), "t.json: sites[1].metric: metric [1, 2, 1] is not positive definite");
  EXPECT_ERROR(doc("[1, 1, 1]"), "t.json: sites[1].metric: metric [1, 1, 1] is not positive definite");  // det 0
  EXPECT_ERROR(doc("[0, 0, 1]"), "t.json: sites[1].metric:");
  EXPECT_EQ(error_of(doc("[1, 0.999999999999, 1]")), "(accepted)");  // det = 2·10⁻¹² − 10⁻²⁴ > 0
}

TEST(SiteSet, CoincidentSitesAreFoundExactly) {
  EXPECT_ERROR(with_domain({"1 1", "0 0", "\"2/2\" 1.0"}, ""), "t.json: sites[0] and sites[2] coincide at (1, 1)");
  EXPECT_ERROR(with_domain({"0 0", "0.1 0", "5 5", "\"1/10\" 0"}, ""),
               "t.json: sites[1] and sites[3] coincide at (0.1, 0)");
  EXPECT_EQ(error_of(with_domain({"0.1 0", "0.1000000000000000000000001 0"}, "")), "(accepted)");
}

TEST(SiteSet, DefaultDomainIsTheBoundingBoxWithAMarginOfOneEighth) {
  const Mesh s = read(with_domain({"0 0", "8 4", "2 1"}, ""));
  expect_polygon(s.domain, {P("-1", "-1"), P("9", "-1"), P("9", "5"), P("-1", "5")});
  // Zero width: the margin comes from the height.
  expect_polygon(read(with_domain({"0 0", "0 16"}, "")).domain, {P("-2", "-2"), P("2", "-2"), P("2", "18"), P("-2", "18")});
  // A single site: margin 1.
  expect_polygon(read(with_domain({"\"1/3\" 3"}, "")).domain,
                 {P("-2/3", "2"), P("4/3", "2"), P("4/3", "4"), P("-2/3", "4")});
}

TEST(SiteSet, GivenDomainIsKept) {
  const Mesh s = read(with_domain({"1 1"}, L_shape));
  expect_polygon(s.domain, {P("0", "0"), P("2", "0"), P("2", "1"), P("1", "1"), P("1", "2"), P("0", "2")});
}

TEST(SiteSet, DomainSyntaxErrors) {
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [1, 0]]"), "t.json: domain: expected an array of at least 3 vertices");
  EXPECT_ERROR(with_domain({"0 0"}, R"({"x": 0})"), "t.json: domain: expected an array of at least 3 vertices");
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [1, 0, 2], [0, 1]]"), "t.json: domain[1]: expected a vertex [x, y]");
  EXPECT_ERROR(with_domain({"0 0"}, R"([[0, 0], [1, 0], [0, "y"]])"), "t.json: domain[2][1]: \"y\" is not an exact number");
}

TEST(SiteSet, DomainEdgesOfLengthZeroAreRejected) {
  EXPECT_ERROR(with_domain({"0 0"}, R"([[0, 0], [1, 0], ["2/2", 0.0], [0, 1]])"),
               "t.json: domain: domain[1] and domain[2] are the same point (1, 0) (edge 1 has length zero)");
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [1, 0], [0, 1], [0, 0]]"),
               "t.json: domain: domain[3] and domain[0] are the same point (0, 0) (edge 3 has length zero)");
}

TEST(SiteSet, DomainFoldingBackIsRejectedButStraightRunsAreAccepted) {
  EXPECT_ERROR(with_domain({"1 1"}, "[[0, 0], [2, 0], [1, 0], [1, 1]]"),
               "t.json: domain: the boundary folds back at domain[1] (2, 0): edge 0 (domain[0] to domain[1]) and "
               "edge 1 (domain[1] to domain[2]) overlap");
  // Three collinear vertices: edges 2 and 0 overlap, the boundary folds back at (0, 0).
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [1, 0], [2, 0]]"), "folds back at domain[0]");
  const Mesh s = read(with_domain({"1 0"}, "[[0, 0], [1, 0], [2, 0], [2, 2], [0, 2]]"));
  EXPECT_EQ(s.domain.size(), 5u);  // the straight vertex (1, 0) is kept
}

TEST(SiteSet, BowTieDomainIsRejectedNamingTheCrossingEdges) {
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [2, 2], [2, 0], [0, 2]]"),
               "t.json: domain: edge 0 (domain[0] to domain[1]) and edge 2 (domain[2] to domain[3]) cross at (1, 1)");
}

TEST(SiteSet, DomainTouchingItselfIsRejected) {
  // Vertex 4 = (2, 0) lies on edge 0: edges 0 and 3 touch there (as do 0 and 4).
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [4, 0], [4, 4], [3, 4], [2, 0], [1, 4], [0, 4]]"),
               "t.json: domain: edge 0 (domain[0] to domain[1]) and edge 3 (domain[3] to domain[4]) touch at (2, 0)");
  // A slit of width zero: edges 0 and 4 overlap along [1, 2] x {0}; the first meeting found is
  // edge 3's end (2, 0) on edge 0.
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [3, 0], [3, 1], [2, 1], [2, 0], [1, 0], [1, 1], [0, 1]]"),
               "t.json: domain: edge 0 (domain[0] to domain[1]) and edge 3 (domain[3] to domain[4]) touch at (2, 0)");
}

TEST(SiteSet, ClockwiseDomainIsRejected) {
  EXPECT_ERROR(with_domain({"0 0"}, "[[0, 0], [0, 1], [1, 1], [1, 0]]"),
               "t.json: domain: the vertices are clockwise; list the vertices counter-clockwise");
  EXPECT_EQ(error_of(with_domain({"0 0"}, "[[0, 0], [1, 0], [1, 1], [0, 1]]")), "(accepted)");
}

TEST(SiteSet, NonConvexDomainAcceptsSitesInTheClosedPolygon) {
  // The reflex corner, a convex corner, a point of an edge, and interior points of both arms.
  EXPECT_EQ(error_of(with_domain({"1 1", "0 0", "\"3/2\" 1", "\"1/2\" \"3/2\"", "\"3/2\" \"1/2\""}, L_shape)),
            "(accepted)");
  // The notch, exactly at its corner (2, 2), and just off the reflex corner into the notch.
  EXPECT_ERROR(with_domain({"0 0", "\"3/2\" \"3/2\""}, L_shape), "t.json: sites[1] (1.5, 1.5) lies outside the domain");
  EXPECT_ERROR(with_domain({"0 0", "2 2"}, L_shape), "t.json: sites[1] (2, 2) lies outside the domain");
  EXPECT_ERROR(with_domain({"0 0", "1.000000000000000000000001 1.000000000000000000000001"}, L_shape),
               "t.json: sites[1] (1.000000000000000000000001, 1.000000000000000000000001) lies outside the domain");
}

TEST(SiteSet, SiteExactlyOnAnEdgeIsAccepted) {
  const std::string triangle = "[[0, 0], [3, 0], [0, 3]]";
  EXPECT_EQ(error_of(with_domain({"1 2", "\"1/3\" \"8/3\"", "0.5 0", "0 3"}, triangle)), "(accepted)");
  EXPECT_ERROR(with_domain({"1 2", "1.0000000000000000000000001 2"}, triangle),
               "t.json: sites[1] (1.0000000000000000000000001, 2) lies outside the domain");
  EXPECT_ERROR(with_domain({"1 1", "-1 0"}, triangle), "t.json: sites[1] (-1, 0) lies outside the domain");
}

TEST(SiteSet, SegmentsAreCheckedAgainstTheSites) {
  const auto doc = [](const std::string& segments) {
    return R"({"sites": [{"x": 0, "y": 0, "metric": [1, 0, 1]}, {"x": 1, "y": 0, "metric": [1, 0, 1]},
                         {"x": 0, "y": 1, "metric": [1, 0, 1]}], "segments": )" + segments + "}";
  };
  const Mesh s = read(doc("[[0, 1], [2, 1]]"));
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_EQ(s.segments[1], (std::pair<int, int>{2, 1}));
  EXPECT_ERROR(doc(R"({"0": 1})"), "t.json: segments: expected an array");
  EXPECT_ERROR(doc("[[0, 1], [2]]"), "t.json: segments[1]: expected [i, j]");
  EXPECT_ERROR(doc("[[0, 3]]"), "t.json: segments[0][1]: expected a site index from 0 to 2, got 3");
  EXPECT_ERROR(doc("[[-1, 0]]"), "t.json: segments[0][0]: expected a site index from 0 to 2, got -1");
  EXPECT_ERROR(doc("[[0, 1.5]]"), "t.json: segments[0][1]: expected a site index");
  EXPECT_ERROR(doc("[[0, 1], [2, 2]]"), "t.json: segments[1]: repeats sites[2]");
  EXPECT_ERROR(doc("[[0, 1], [0, 2], [1, 0]]"), "t.json: segments[2]: repeats segments[0] (sites[1] to sites[0])");
}

TEST(SiteSet, FilesAreNamedInMessages) {
  const std::filesystem::path missing = std::filesystem::temp_directory_path() / "anisocert_no_such_file.json";
  std::filesystem::remove(missing);
  try {
    read_mesh_json_file(missing.string());
    ADD_FAILURE() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string() + ": cannot open"), std::string::npos) << e.what();
  }
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "anisocert_io_site_set_test.json";
  std::ofstream(file) << with_domain({"0 0", "0 0"}, "");
  try {
    read_mesh_json_file(file.string());
    ADD_FAILURE() << "coincident sites were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": sites[0] and sites[1] coincide at (0, 0)");
  }
  std::ofstream(file) << with_domain({"0 0", "1 0"}, "");
  EXPECT_EQ(read_mesh_json_file(file.string()).sites.size(), 2u);
  std::filesystem::remove(file);
}
