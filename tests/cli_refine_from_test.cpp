// `anisocert refine --from MESH` (issue 41) as a user runs it: a peer's mesh becomes a certified
// mesh, checked here by a second command (`anisocert dual`, the oracle's own verdict on the file
// written) and against the input (every input vertex, rounded to the nearest double, is a vertex
// of the output; the counts the report gives are the files'); --coarsen removes only interior
// vertices and keeps the certificate, --relocate moves only interior ones and keeps it; --off-centres changes where BWY inserts and keeps the
// certificate; the star refiner starts from the same vertices and is certified locally uniform;
// every bad input is one line, exit 2, nothing written.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

namespace {

namespace fs = std::filesystem;

const std::string fixtures = std::string(ANISOCERT_REGRESSIONS_DIR) + "/../peers/fixtures/";
// FreeFem's adaptmesh of the L-shape for the coarse shock field (tests/peers/fixtures/README.md).
// It is also the regression of the corner ping-pong: before the concentric shells
// (refiners/common/corner_shells.hpp) BWY split the edges at the re-entrant corner, 20° in its
// metric, down to 10⁻⁶ of the corner and stopped there.
const std::string freefem_l = fixtures + "freefem-lshape-shock-coarse.msh";
const std::string shock_coarse = " --field shock --param h=0.1";

fs::path fresh(const std::string& name) { return fresh_folder("cli_refine_from", name); }

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The sites of an anisocert JSON mesh as doubles (each text is the exact decimal of a double).
std::set<std::pair<double, double>> sites_of(const fs::path& json) {
  std::set<std::pair<double, double>> s;
  const auto j = nlohmann::json::parse(read(json));
  for (const auto& site : j["sites"])
    s.insert({std::stod(site["x"].get<std::string>()), std::stod(site["y"].get<std::string>())});
  return s;
}

// The vertices of a FreeFem .msh file ("nv nt ne", then "x y label" per vertex), each read as the
// nearest double.
std::vector<std::pair<double, double>> freefem_vertices(const std::string& path) {
  std::ifstream in(path);
  std::size_t nv = 0, nt = 0, ne = 0;
  in >> nv >> nt >> ne;
  std::vector<std::pair<double, double>> v;
  for (std::size_t k = 0; k < nv; ++k) {
    std::string x, y, label;
    in >> x >> y >> label;
    v.push_back({std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr)});
  }
  return v;
}

// Whether a decimal text ("0.411121466087", "-1", "0.5") denotes a double, by integer arithmetic
// on its digits (not the program's parser): n/10ᵏ is dyadic exactly when 5ᵏ divides n, and it is a
// double when it is dyadic with at most 53 significant bits (FreeFem's 12 digits always fit).
bool decimal_is_dyadic(const std::string& text) {
  const std::size_t dot = text.find('.');
  const std::string frac = dot == std::string::npos ? "" : text.substr(dot + 1);
  std::string digits = (dot == std::string::npos ? text : text.substr(0, dot)) + frac;
  if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.erase(0, 1);
  unsigned long long n = std::stoull(digits), five = 1;
  for (std::size_t k = 0; k < frac.size(); ++k) five *= 5;
  return n % five == 0;
}

// "N in, A added, R removed" from the report.
std::array<std::size_t, 3> counts(const std::string& report) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(report, m, std::regex("vertices: ([0-9]+) in, ([0-9]+) added, ([0-9]+) removed"))) << report;
  if (m.size() < 4) return {0, 0, 0};
  return {std::stoul(m[1]), std::stoul(m[2]), std::stoul(m[3])};
}

// The certifier's unit-edge share after the run, from the report's "after:" line (in %).
double unit_share_after(const std::string& report) {
  std::smatch s;
  EXPECT_TRUE(std::regex_search(report, s, std::regex("after: .*unit edges ([0-9.]+)%"))) << report;
  return s.size() > 1 ? std::stod(s[1]) : 0.0;
}

// FreeFem's coarse L-shape refined (`before`) and then changed by a post-pass (`after`): the sites
// of `after` that are not `before`'s lie strictly inside the L-shape (0 < x, y < 1, not in
// [1/2, 1]²), and there are some; every vertex of `before` on ∂Ω (BWY's boundary splits too) is in
// `after`; each site of `after` has the field's metric at its place (`metric --at`, a second
// command, evaluates the field there).
void expect_moves_inside_with_the_fields_metric(const fs::path& d, const std::string& before_mesh, const std::string& after_mesh) {
  const auto before = sites_of(before_mesh), after = sites_of(after_mesh);
  std::size_t moved = 0;
  for (const auto& [x, y] : after)
    if (!before.count({x, y})) {
      ++moved;
      EXPECT_TRUE(x > 0 && y > 0 && x < 1 && y < 1 && !(x >= 0.5 && y >= 0.5)) << x << ", " << y;
    }
  EXPECT_GT(moved, 0u);
  for (const auto& [x, y] : before)
    if (x == 0 || y == 0 || x == 1 || y == 1 || (x == 0.5 && y >= 0.5) || (y == 0.5 && x >= 0.5)) {
      EXPECT_TRUE(after.count({x, y})) << x << ", " << y;
    }
  const std::string field_mesh = (d / "field.json").string();
  ASSERT_EQ(run("metric --field shock --param h=0.1 --at " + after_mesh + " -o " + field_mesh).exit_code, 0);
  const auto ours = nlohmann::json::parse(read(after_mesh))["sites"], field = nlohmann::json::parse(read(field_mesh))["sites"];
  ASSERT_EQ(ours.size(), field.size());
  for (std::size_t k = 0; k < ours.size(); ++k) EXPECT_EQ(ours[k]["metric"], field[k]["metric"]) << "site " << k;
}

TEST(RefineFrom, FreeFemsLShapeBecomesACertifiedDualKeepingEveryVertex) {
  const fs::path d = fresh("freefem");
  const Outcome r = run("refine --quiet --algo bwy --from " + freefem_l + shock_coarse + " -o " + (d / "out.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("certified: the exact dual of D|Ω"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stopped: no rule of BWY §3.2.2 applies"), std::string::npos) << r.out;  // the ping-pong ends
  // The oracle's verdict on the file written, by another command.
  const Outcome dual = run("dual --quiet " + (d / "out.json").string());
  EXPECT_EQ(dual.exit_code, 0) << dual.out << dual.err;
  const auto input = freefem_vertices(freefem_l);
  const auto output = sites_of(d / "out.json");
  for (const auto& v : input) EXPECT_TRUE(output.count(v)) << v.first << ", " << v.second;
  const auto [in, added, removed] = counts(r.out);
  EXPECT_EQ(in, input.size());
  EXPECT_EQ(removed, 0u);
  EXPECT_EQ(in + added, output.size());
  // FreeFem writes 12-digit decimals: the run counts exactly the vertices with a coordinate that
  // is not a double, counted here from the file's text.
  std::size_t not_doubles = 0;
  {
    std::ifstream in(freefem_l);
    std::size_t nv = 0, nt = 0, ne = 0;
    in >> nv >> nt >> ne;
    for (std::size_t k = 0; k < nv; ++k) {
      std::string x, y, label;
      in >> x >> y >> label;
      not_doubles += !decimal_is_dyadic(x) || !decimal_is_dyadic(y);
    }
  }
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("([0-9]+) rounded to the nearest doubles"))) << r.out;
  EXPECT_GT(not_doubles, 0u);
  EXPECT_EQ(std::stoul(m[1]), not_doubles);
}

// --coarsen removes interior vertices only and keeps the certificate; with --collapse too.
TEST(RefineFrom, CoarsenRemovesInteriorVerticesOnlyAndKeepsTheCertificate) {
  const fs::path d = fresh("coarsen");
  const Outcome r = run("refine --quiet --algo bwy --coarsen --from " + freefem_l + shock_coarse + " -o " + (d / "out.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(run("dual --quiet " + (d / "out.json").string()).exit_code, 0);
  const auto [in, added, removed] = counts(r.out);
  EXPECT_GT(removed, 0u) << r.out;
  const auto output = sites_of(d / "out.json");
  EXPECT_EQ(in + added - removed, output.size());
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("coarsened: ([0-9]+) vertices removed"))) << r.out;
  EXPECT_EQ(std::stoul(m[1]), removed);
  // Every vertex on ∂Ω (x or y 0 or 1, or on the re-entrant edges x = 1/2, y ≥ 1/2 and y = 1/2, x ≥ 1/2) stays.
  for (const auto& [x, y] : freefem_vertices(freefem_l)) {
    const bool boundary = x == 0 || y == 0 || x == 1 || y == 1 || (x == 0.5 && y >= 0.5) || (y == 0.5 && x >= 0.5);
    if (boundary) {
      EXPECT_TRUE(output.count({x, y})) << x << ", " << y;
    }
  }
  // Its unit share is the certifier's: no lower than without --coarsen.
  const std::string plain_mesh = (d / "plain.json").string();
  const Outcome plain = run("refine --quiet --algo bwy --from " + freefem_l + shock_coarse + " -o " + plain_mesh);
  ASSERT_EQ(plain.exit_code, 0) << plain.out << plain.err;
  EXPECT_GT(unit_share_after(r.out), unit_share_after(plain.out)) << r.out << plain.out;

  // --collapse: a removal may move the other end of the vertex's shortest edge to the edge's
  // midpoint, in the same trial. Some removals are collapses, the report's two counts of removals
  // agree and the output has as many sites as they say; `dual` certifies the file; ∂Ω's vertices
  // stay; the sites that are not the plain run's lie strictly inside the L-shape, each with the
  // field's metric there (`metric --at`).
  const std::string collapsed_mesh = (d / "collapsed.json").string();
  const Outcome c = run("refine --quiet --algo bwy --coarsen --collapse --from " + freefem_l + shock_coarse + " -o " + collapsed_mesh);
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_EQ(run("dual --quiet " + collapsed_mesh).exit_code, 0);
  ASSERT_TRUE(std::regex_search(c.out, m, std::regex("coarsened: ([0-9]+) vertices removed \\(([0-9]+) by an edge collapse"))) << c.out;
  EXPECT_EQ(std::stoul(m[1]), counts(c.out)[2]);
  EXPECT_EQ(counts(c.out)[0] + counts(c.out)[1] - counts(c.out)[2], sites_of(collapsed_mesh).size());
  EXPECT_GT(std::stoul(m[2]), 0u) << c.out;
  expect_moves_inside_with_the_fields_metric(d, plain_mesh, collapsed_mesh);
}

// --relocate moves interior vertices only, never adds or removes one, and keeps the certificate:
// `dual` (a second command) certifies the file; each site's metric is the field's at its new place
// (`metric --at`, a second command, evaluates the field there); the certifier's unit share rises.
TEST(RefineFrom, RelocateMovesInteriorVerticesOnlyAndKeepsTheCertificate) {
  const fs::path d = fresh("relocate");
  const std::string plain_mesh = (d / "plain.json").string(), moved_mesh = (d / "moved.json").string();
  const Outcome plain = run("refine --quiet --algo bwy --from " + freefem_l + shock_coarse + " -o " + plain_mesh);
  const Outcome r = run("refine --quiet --algo bwy --relocate --from " + freefem_l + shock_coarse + " -o " + moved_mesh);
  ASSERT_EQ(plain.exit_code, 0) << plain.out << plain.err;
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(run("dual --quiet " + moved_mesh).exit_code, 0);
  const auto [in, added, removed] = counts(r.out);
  EXPECT_EQ(removed, 0u) << r.out;
  EXPECT_EQ(counts(plain.out), (std::array<std::size_t, 3>{in, added, 0}));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("relocated: ([0-9]+) moves of a vertex"))) << r.out;
  EXPECT_GT(std::stoul(m[1]), 0u) << r.out;
  // The same number of sites as the run it moved.
  EXPECT_EQ(sites_of(moved_mesh).size(), sites_of(plain_mesh).size());
  expect_moves_inside_with_the_fields_metric(d, plain_mesh, moved_mesh);
  // A round keeps a batch only when the share does not drop; that it rises here (the run is
  // deterministic) is measured: a relocation that never kept a move, or kept the wrong ones, fails.
  EXPECT_GT(unit_share_after(r.out), unit_share_after(plain.out)) << r.out << plain.out;
}

TEST(RefineFrom, OffCentresMoveBwysInsertionsAndKeepTheCertificate) {
  // The share of unit edges they give is measured, not promised (docs/validation.md: up on the
  // default shock field, down on the coarse one); that they change where BWY inserts, and that the
  // oracle still certifies the result, is the property (BWY_R and LS_S9 run half their cases with them).
  const fs::path d = fresh("offcentres");
  for (const std::string& extra : {std::string(), std::string(" --off-centres")}) {
    const std::string mesh = (d / (extra.empty() ? "vertex.json" : "off.json")).string();
    const Outcome r = run("refine --quiet --algo bwy" + shock_coarse + extra + " -o " + mesh);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(run("dual --quiet " + mesh).exit_code, 0) << extra;
    // Rules 4 and 5 choose among the vertices BWY §3.2.2 allows only with off-centres, and then
    // some of the time another than the one they fired at (the vertex whose radius is nearest 1).
    std::smatch m;
    const bool counted = std::regex_search(r.out, m, std::regex("rules 4 and 5 took another vertex they allow ([0-9]+) times"));
    EXPECT_EQ(counted, !extra.empty()) << r.out;
    if (counted) {
      EXPECT_GT(std::stoul(m[1]), 0u) << r.out;
    }
  }
  EXPECT_NE(sites_of(d / "vertex.json"), sites_of(d / "off.json"));
  EXPECT_EQ(run("refine --quiet --algo ls --field constant --off-centres").err,
            "anisocert: --off-centres: LS with the constant field runs Del_M, which inserts at circumcentres only\n");
}

// The star refiner from the same mesh, for a constant metric: every vertex of the mesh is a site from
// the start (beside Ω's corners), ∂Ω's subsegments, axis-parallel with 12-digit ends whose midpoints
// are no doubles, are split at the double nearest the midpoint, exactly on ∂Ω; and the output is
// locally uniform by `certify`, a second command (a mesh with a segment inside Ω is refused: the
// bad inputs below).
TEST(RefineFrom, StarStartsFromEveryVertexAndIsCertifiedLocallyUniform) {
  const fs::path d = fresh("star");
  const std::string out = (d / "out.json").string();
  const Outcome r = run("refine --quiet --algo star --field constant --from " + freefem_l + " -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("certified: locally uniform"), std::string::npos) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("encroachment ([0-9]+),"))) << r.out;
  EXPECT_GT(std::stoul(m[1]), 0u);  // ∂Ω was split
  const auto input = freefem_vertices(freefem_l);
  const auto output = sites_of(out);
  for (const auto& v : input) EXPECT_TRUE(output.count(v)) << v.first << ", " << v.second;
  const auto [in, added, removed] = counts(r.out);
  EXPECT_EQ(in, input.size());
  EXPECT_EQ(in + added, output.size());
  const Outcome c = run("certify " + out);
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("valid (a triangulation of the domain, segments are unions of edges): holds"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("locally uniform (every triangle at v has an empty M_v-circumellipse): holds"), std::string::npos) << c.out;
  // The splits are off any coarse grid: some output site on ∂Ω (x or y 0 or 1, or on the re-entrant
  // edges x = 1/2, y ≥ 1/2 and y = 1/2, x ≥ 1/2) that is no input vertex has a coordinate along its
  // edge that is no multiple of 2⁻⁴⁰ (exact midpoints of the 12-digit ends would not be doubles).
  std::size_t new_on_boundary = 0, fine = 0;
  for (const auto& [x, y] : output) {
    const bool vertical = x == 0 || x == 1 || (x == 0.5 && y >= 0.5), horizontal = y == 0 || y == 1 || (y == 0.5 && x >= 0.5);
    if (!(vertical || horizontal) || std::count(input.begin(), input.end(), std::pair{x, y})) continue;
    ++new_on_boundary;
    const double along = vertical ? y : x;
    fine += std::ldexp(along, 40) != std::floor(std::ldexp(along, 40));
  }
  EXPECT_EQ(new_on_boundary, std::stoul(m[1]));
  EXPECT_GT(fine, 0u);
}

// The unit square in the metric 100 I, its six triangles around the constrained segment from
// (1/4, 1/2) to (3/4, 1/2) (a JSON mesh's "segments").
std::string slit_square(const fs::path& d) {
  std::string sites;
  for (const auto& [x, y] : {std::pair{"0", "0"}, {"1", "0"}, {"1", "1"}, {"0", "1"}, {"0.25", "0.5"}, {"0.75", "0.5"}})
    sites += std::string(sites.empty() ? "" : ", ") + "{\"x\": \"" + x + "\", \"y\": \"" + y + "\", \"metric\": [\"100\", \"0\", \"100\"]}";
  const std::string path = (d / "slit.json").string();
  std::ofstream(path) << "{\"sites\": [" << sites
                      << "], \"triangles\": [[0, 1, 5], [0, 5, 4], [0, 4, 3], [1, 2, 5], [2, 3, 4], [2, 4, 5]], \"segments\": [[4, 5]]}\n";
  return path;
}

// A constrained segment inside Ω (a JSON mesh's "segments", as a Medit file's declared Edges
// inside Ω) is an interior segment of X: the output has it as a union of its edges, checked here
// from the triangles: the sites on the segment y = 1/2, 1/4 <= x <= 3/4, sorted by x, are joined
// one to the next by edges of the mesh.
// With --coarsen --relocate too: each trial needs the segment's pieces to be edges of the dual.
TEST(RefineFrom, AConstrainedSegmentInsideStaysAUnionOfEdges) {
  for (const std::string& extra : {std::string(), std::string(" --coarsen --relocate")}) {
    SCOPED_TRACE(extra);
    const fs::path d = fresh("segment" + std::to_string(extra.size()));
    const std::string mesh = slit_square(d);
    const Outcome r = run("refine --quiet --algo bwy --from " + mesh + extra + " -o " + (d / "out.json").string());
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("1 interior segments"), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(read(d / "out.json"));
    std::vector<std::pair<double, int>> on;  // (x, site) on the segment
    for (std::size_t k = 0; k < j["sites"].size(); ++k) {
      const double x = std::stod(j["sites"][k]["x"].get<std::string>()), y = std::stod(j["sites"][k]["y"].get<std::string>());
      if (y == 0.5 && x >= 0.25 && x <= 0.75) on.push_back({x, static_cast<int>(k)});
    }
    std::sort(on.begin(), on.end());
    ASSERT_GE(on.size(), 3u);  // the metric 100 I splits it
    std::set<std::pair<int, int>> edges;
    for (const auto& t : j["triangles"])
      for (int i = 0; i < 3; ++i) {
        const int a = t[i].get<int>(), b = t[(i + 1) % 3].get<int>();
        edges.insert({std::min(a, b), std::max(a, b)});
      }
    for (std::size_t k = 0; k + 1 < on.size(); ++k)
      EXPECT_TRUE(edges.count({std::min(on[k].second, on[k + 1].second), std::max(on[k].second, on[k + 1].second)})) << on[k].first;
    EXPECT_EQ(run("dual --quiet " + (d / "out.json").string()).exit_code, 0);
  }
}

// The degenerate input: a 5 × 5 grid of the unit square in the metric 16 I, every square's corners
// cocircular (each Voronoi vertex of degree 4, an exact tie). The grid is already a dual of D|Ω
// (any diagonal of a cocircular square is a tie): nothing is added, and the oracle certifies it.
TEST(RefineFrom, AGridOfCocircularSquaresIsCertifiedAsItIs) {
  const fs::path d = fresh("grid");
  std::string sites, triangles;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i)
      sites += std::string(sites.empty() ? "" : ", ") + "{\"x\": \"" + std::to_string(i) + "/4\", \"y\": \"" + std::to_string(j) +
               "/4\", \"metric\": [\"16\", \"0\", \"16\"]}";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int a = 5 * j + i;
      triangles += std::string(triangles.empty() ? "" : ", ") + "[" + std::to_string(a) + ", " + std::to_string(a + 1) + ", " +
                   std::to_string(a + 6) + "], [" + std::to_string(a) + ", " + std::to_string(a + 6) + ", " + std::to_string(a + 5) + "]";
    }
  std::ofstream(d / "grid.json") << "{\"sites\": [" << sites << "], \"triangles\": [" << triangles << "]}\n";
  const Outcome r = run("refine --quiet --algo bwy --from " + (d / "grid.json").string() + " -o " + (d / "out.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("vertices: 25 in, 0 added, 0 removed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("16 on the boundary, 0 rounded"), std::string::npos) << r.out;
  // The 16 sides and 16 diagonals of length 1 and exactly √2 in 16 I, and 24 more sides: unit before
  // and after (the output's metrics are the file's, to the bit, at its vertices).
  EXPECT_NE(r.out.find("before: 25 vertices, 32 triangles, unit edges 100.0% of 56"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("after:  25 vertices, 32 triangles, unit edges 100.0% of 56"), std::string::npos) << r.out;
  EXPECT_EQ(sites_of(d / "out.json").size(), 25u);
  EXPECT_EQ(run("dual --quiet " + (d / "out.json").string()).exit_code, 0);
}

// The bad inputs: one line naming what is wrong, exit 2, nothing written.
void refused(const std::string& args, const std::string& says, const fs::path& d) {
  const std::string out = (d / "out.json").string();
  const Outcome r = run("refine --quiet " + args + " -o " + out);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

// A JSON mesh of `sites` (x, y, m11, m12, m22 as texts) and `triangles`.
std::string json_mesh(const fs::path& d, const std::string& name, const std::vector<std::array<std::string, 5>>& sites,
                      const std::string& triangles) {
  std::string s = "{\"sites\": [";
  for (std::size_t k = 0; k < sites.size(); ++k)
    s += std::string(k ? ", " : "") + "{\"x\": \"" + sites[k][0] + "\", \"y\": \"" + sites[k][1] + "\", \"metric\": [\"" + sites[k][2] + "\", \"" +
         sites[k][3] + "\", \"" + sites[k][4] + "\"]}";
  const std::string path = (d / name).string();
  std::ofstream(path) << s << "], \"triangles\": " << triangles << "}\n";
  return path;
}

TEST(RefineFrom, BadInputIsOneLineAndExit2) {
  const fs::path d = fresh("bad");
  const auto I = [](const std::string& x, const std::string& y) { return std::array<std::string, 5>{x, y, "100", "0", "100"}; };
  const std::string square = json_mesh(d, "square.json", {I("0", "0"), I("1", "0"), I("1", "1"), I("0", "1"), I("0.4", "0.6")},
                                       "[[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]");
  // Two triangles over the same place: no triangulation.
  refused("--algo bwy --from " + json_mesh(d, "overlap.json", {I("0", "0"), I("1", "0"), I("1", "1"), I("0", "1")}, "[[0, 1, 2], [0, 1, 3], [0, 2, 3]]"),
          "is not a valid triangulation", d);
  // A metric that is not positive definite at vertex 4.
  refused("--algo bwy --from " + json_mesh(d, "indefinite.json",
                                          {I("0", "0"), I("1", "0"), I("1", "1"), I("0", "1"), {"0.5", "0.5", "1", "2", "1"}},
                                          "[[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]"),
          "is not positive definite", d);
  // Two triangles that meet at one vertex: the boundary pinches there.
  refused("--algo bwy --from " + json_mesh(d, "bowtie.json", {I("0", "0"), I("1", "0"), I("1", "1"), I("2", "1"), I("2", "2")},
                                          "[[0, 1, 2], [2, 3, 4]]"),
          "passes through site 2 twice", d);
  // A square with a square hole: the boundary is two loops.
  {
    std::vector<std::array<std::string, 5>> v;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) v.push_back(I(std::to_string(i), std::to_string(j)));
    std::string t = "[";
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        if (i == 1 && j == 1) continue;
        const int a = 4 * j + i;
        t += (t.size() > 1 ? ", " : "") + std::string("[") + std::to_string(a) + ", " + std::to_string(a + 1) + ", " + std::to_string(a + 5) +
             "], [" + std::to_string(a) + ", " + std::to_string(a + 5) + ", " + std::to_string(a + 4) + "]";
      }
    refused("--algo bwy --from " + json_mesh(d, "annulus.json", v, t + "]"), "more than one loop", d);
  }
  refused("--algo bwy --exact-sites --from " + square, "vertex 4 (0.4, 0.6) is not a pair of doubles", d);
  refused("--algo bwy --from " + fixtures + "gmsh-lshape-shock-coarse.msh", "has no metric (give --metric FILE or --field NAME)", d);
  refused("--algo bwy --domain square --from " + square, "--domain and --from", d);
  refused("--algo star --coarsen --from " + square, "--coarsen: --algo star is certified locally uniform", d);
  refused("--algo star --relocate --from " + square, "--relocate: --algo star is certified locally uniform", d);
  refused("--algo bwy --relocate", "go with --from MESH", d);
  refused("--algo bwy --collapse", "go with --from MESH", d);
  refused("--algo bwy --collapse --from " + square, "--collapse: it says how --coarsen removes vertices; give --coarsen too", d);
  refused("--algo star --from " + slit_square(d), "--algo star keeps no interior segments (LU §4.1 protects ∂Ω only)", d);
  refused("--algo bwy --metric m.sol", "go with --from MESH", d);
  refused("--algo bwy --from " + (d / "missing.msh").string(), "missing.msh", d);
}

}  // namespace
