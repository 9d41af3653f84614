#include "io/reports/certify_report.hpp"

#include "io/reports/printed.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <functional>
#include <sstream>

namespace anisocert::io {
namespace {

WitnessLines texts(const oracle::WitnessList& ws) {
  WitnessLines l{{}, ws.count()};
  for (std::size_t i = 0; i < ws.described().size() && i < 3; ++i) l.first.push_back(ws.described()[i].text);
  return l;
}

WitnessLines texts(const std::vector<std::string>& lines, std::size_t count) {
  return {std::vector<std::string>(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(3, lines.size()))), count};
}

// An enclosure to 10 significant digits, its ends rounded outward in print.
std::string enclosure_text(const FilterInterval& q) { return "[" + outward(q.lo, false) + ", " + outward(q.hi, true) + "]"; }
ReportJson enclosure_json(const FilterInterval& q) { return ReportJson::array({q.lo, q.hi}); }

const char* verdict(const CheckReport& c) { return !c.is_verdict ? "measured" : c.holds ? "holds" : "FAILS"; }

void add_validity(const oracle::CertifyReport& r, CertifyVerdict& v) {
  const oracle::TriangulationCheck& t = *r.valid;
  const std::string more = t.failure_count > t.failures.size()
                               ? " (" + std::to_string(t.failure_count) + " failures, the first " +
                                     std::to_string(t.failures.size()) + " described)"
                               : "";
  v.checks.push_back({"valid", "valid (a triangulation of the domain, segments are unions of edges)", "valid",
                      r.valid_holds(), true, more, "",
                      {texts(t.failures, t.failure_count), texts(r.segment_failures, r.segment_failure_count)},
                      {{"holds", r.valid_holds()}, {"checks_run", t.checks_run}, {"failure_count", t.failure_count},
                       {"bad_triangle_count", t.bad_cells.size()}, {"bad_edge_count", t.bad_edges.size()},
                       {"segment_failure_count", r.segment_failure_count}}});
}

void add_uniform(const oracle::CertifyReport& r, CertifyVerdict& v) {
  const bool holds = r.uniform_violations.empty();
  const std::string unmeasured =
      r.unmeasured ? ", " + std::to_string(r.unmeasured) + " flat or clockwise triangles cannot be checked" : "";
  v.checks.push_back({"locally_uniform", "locally uniform (every triangle at v has an empty M_v-circumellipse)",
                      "locally uniform", holds, true,
                      " (" + std::to_string(r.incircle_tests) + " nearby sites tested exactly, " +
                          std::to_string(r.uniform_ties.count()) + " cocircular ties" + unmeasured + ")",
                      " (" + std::to_string(r.uniform_ties.count()) + " ties)", {texts(r.uniform_violations)},
                      {{"holds", holds}, {"incircle_tests", r.incircle_tests}, {"unmeasured_triangles", r.unmeasured},
                       {"violation_count", r.uniform_violations.count()}, {"tie_count", r.uniform_ties.count()}}});
}

void add_lengths(const oracle::LengthReport& l, const BoundTexts& b, CertifyVerdict& v) {
  const bool bounded = !b.length_lo.empty();
  const std::string range = "[" + excerpt(b.length_lo) + ", " + excerpt(b.length_hi) + "]";
  v.checks.push_back(
      {"lengths",
       bounded ? "every edge length in its endpoints' metrics within " + range : "edge lengths in their endpoints' metrics",
       bounded ? "lengths in " + range : "lengths", l.range_violations.empty(), bounded,
       " (" + percent(l.unit_edges, l.edges) + " of " + std::to_string(l.edges) +
           " edges have both lengths in [1/√2, √2]; shortest ≈ " + as_printed(l.shortest) + ", longest ≈ " +
           as_printed(l.longest) + ")",
       " (" + percent(l.unit_edges, l.edges) + " unit)", {texts(l.range_violations)},
       {{"range", bounded ? ReportJson::array({b.length_lo, b.length_hi}) : ReportJson(nullptr)}, {"holds", l.range_violations.empty()},
        {"edges", l.edges}, {"unit_edges", l.unit_edges}, {"shortest", l.shortest}, {"longest", l.longest},
        {"shortest_edge", l.shortest_edge}, {"longest_edge", l.longest_edge}, {"violation_count", l.range_violations.count()}}});
}

void add_quality(const oracle::QualityReport& q, const BoundTexts& b, CertifyVerdict& v, const std::string& element = "triangle") {
  const bool bounded = !b.min_quality.empty();
  std::string median;
  ReportJson qj = ReportJson::array();
  for (const auto& [p, e] : q.quantiles) {
    if (p == 0.5) median = ", median ∈ " + enclosure_text(e);
    qj.push_back({{"p", p}, {"enclosure", enclosure_json(e)}});
  }
  const std::string undecided =
      q.undecided ? ", " + std::to_string(q.undecided) + (element == "triangle" ? " flat or clockwise triangles" : " flat tetrahedra") + " not measured"
                  : "";
  v.checks.push_back(
      {"quality", bounded ? "mean-ratio quality >= " + excerpt(b.min_quality) + " in each vertex's metric" : "mean-ratio quality in the metrics",
       bounded ? "quality >= " + excerpt(b.min_quality) : "quality", q.violations.empty(), bounded,
       " (least ∈ " + enclosure_text(q.worst) + " at " + element + " " + std::to_string(q.worst_triangle) + median + undecided + ")",
       "", {texts(q.violations)},
       {{"threshold", bounded ? ReportJson(b.min_quality) : ReportJson(nullptr)}, {"holds", q.violations.empty()},
        {"measured", q.measured}, {"unmeasured", q.undecided}, {"least", enclosure_json(q.worst)},
        {"least_" + element, q.worst_triangle}, {"quantiles", qj}, {"violation_count", q.violations.count()}}});
}

void add_angles(const oracle::AngleReport& a, const BoundTexts& b, CertifyVerdict& v, const std::string& element = "triangle") {
  const bool bounded = !b.min_angle.empty();
  const bool holds = a.violations.empty() && a.undecided_triangles.empty();
  const bool three = element == "tetrahedron";
  const std::string undecided =
      a.undecided_triangles.empty() ? "" : ", " + std::to_string(a.undecided_triangles.size()) + " " + element + "s undecided at 8192 bits";
  const std::string largest = three ? "; largest ≈ " + as_printed(a.largest) + "°, tetrahedron " + std::to_string(a.largest_triangle) : "";
  const std::string what = three ? "dihedral angle" : "angle";
  v.checks.push_back({"angles", bounded ? "every " + what + " >= " + excerpt(b.min_angle) + "° in " + (three ? "its edge's ends' metrics" : "its vertex's metric")
                                        : what + "s in the vertices' metrics",
                      bounded ? what + "s >= " + excerpt(b.min_angle) + "°" : what + "s", holds, bounded,
                      " (smallest ≈ " + as_printed(a.smallest) + "°, " + element + " " + std::to_string(a.smallest_triangle) + largest + undecided + ")",
                      "", {texts(a.violations)},
                      {{"threshold_degrees", bounded ? ReportJson(b.min_angle) : ReportJson(nullptr)}, {"holds", holds},
                       {"measured", a.measured}, {"unmeasured", a.undecided}, {"smallest_degrees", a.smallest},
                       {"smallest_" + element, a.smallest_triangle}, {"largest_degrees", a.largest}, {"largest_" + element, a.largest_triangle},
                       {"undecided_count", a.undecided_triangles.size()}, {"violation_count", a.violations.count()}}});
}

// LU's bounds (Definition 3.10's radius-edge ratio ≤ ρ₀ in each vertex's metric, the distortion
// ≤ γ₀ between the vertices of each element), with the worst measured.
void add_radius_edge(double worst, int element, int vertex, const oracle::WitnessList& violations, const BoundTexts& b, CertifyVerdict& v,
                     const std::string& kind = "triangle") {
  const bool holds = violations.empty();
  v.checks.push_back({"radius_edge", "radius-edge ratio ≤ " + excerpt(b.rho0) + " in each vertex's metric", "radius-edge ≤ " + excerpt(b.rho0),
                      holds, true,
                      " (worst ≈ " + as_printed(worst) + ", " + kind + " " + std::to_string(element) + ", vertex " + std::to_string(vertex) + ")",
                      "", {texts(violations)},
                      {{"threshold", b.rho0}, {"holds", holds}, {"worst", worst}, {"worst_" + kind, element}, {"worst_vertex", vertex},
                       {"violation_count", violations.count()}}});
}

void add_distortion(double worst, int element, const oracle::WitnessList& violations, const BoundTexts& b, CertifyVerdict& v,
                    const std::string& kind = "triangle") {
  const bool holds = violations.empty();
  v.checks.push_back({"distortion", "distortion ≤ " + excerpt(b.gamma0) + " between the vertices of each " + kind,
                      "distortion ≤ " + excerpt(b.gamma0), holds, true,
                      " (worst ≈ " + as_printed(worst) + ", " + kind + " " + std::to_string(element) + ")", "", {texts(violations)},
                      {{"threshold", b.gamma0}, {"holds", holds}, {"worst", worst}, {"worst_" + kind, element},
                       {"violation_count", violations.count()}}});
}

void add_validity3(const oracle::Certify3Report& r, CertifyVerdict& v) {
  const oracle::TetrahedralizationCheck& t = *r.valid;
  const std::string more = t.failure_count > t.failures.size()
                               ? " (" + std::to_string(t.failure_count) + " failures, the first " + std::to_string(t.failures.size()) +
                                     " described)"
                               : "";
  const std::string orientation =
      t.orientation.empty() ? "" : ", " + t.orientation + " orientation" + (t.orientation == "positive" ? " (Medit's)" : "");
  v.checks.push_back({"valid", "valid (tetrahedra on opposite sides of each inner face, a closed 2-manifold boundary; not checked: that it does not cross itself)", "valid",
                      r.valid_holds(), true,
                      more + " (" + std::to_string(t.boundary_faces) + " boundary faces" +
                          (t.declared_interfaces ? ", " + std::to_string(t.declared_interfaces) + " declared interface triangles" : "") +
                          (t.declared_both_sides ? ", " + std::to_string(t.declared_both_sides) + " triangles declared from both sides" : "") +
                          orientation + ")",
                      "",
                      {texts(t.failures, t.failure_count)},
                      {{"holds", r.valid_holds()}, {"checks_run", t.checks_run}, {"orientation", t.orientation},
                       {"boundary_faces", t.boundary_faces}, {"interior_faces", t.interior_faces},
                       {"declared_interfaces", t.declared_interfaces}, {"declared_both_sides", t.declared_both_sides}, {"failure_count", t.failure_count},
                       {"bad_tetrahedron_count", t.bad_tetrahedra.size()}}});
}

void add_uniform3(const oracle::Certify3Report& r, CertifyVerdict& v) {
  const bool holds = r.uniform_violations.empty();
  const std::string unmeasured = r.unmeasured ? ", " + std::to_string(r.unmeasured) + " flat tetrahedra cannot be checked" : "";
  v.checks.push_back({"locally_uniform", "locally uniform (every tetrahedron at v has an empty M_v-circumsphere)", "locally uniform", holds,
                      true,
                      " (" + std::to_string(r.insphere_tests) + " nearby vertices tested exactly, " +
                          std::to_string(r.uniform_ties.count()) + " cospherical ties" + unmeasured + ")",
                      " (" + std::to_string(r.uniform_ties.count()) + " ties)", {texts(r.uniform_violations)},
                      {{"holds", holds}, {"insphere_tests", r.insphere_tests}, {"unmeasured_tetrahedra", r.unmeasured},
                       {"violation_count", r.uniform_violations.count()}, {"tie_count", r.uniform_ties.count()}}});
}

// LU's sliver measure (oracle/certify/quasi_cosphericity.hpp): measured, with exact counts at γ₀.
void add_cosphericity3(const oracle::CosphericityReport& c, const BoundTexts& b, CertifyVerdict& v) {
  const auto pair = [](const int (&t)[2]) { return ReportJson::array({t[0], t[1]}); };
  const auto pair_text = [](const int (&t)[2]) { return "tetrahedra " + std::to_string(t[0]) + " and " + std::to_string(t[1]); };
  std::string detail = " (" + std::to_string(c.configurations) + " pairs of tetrahedra sharing a face";
  if (c.least_tetrahedra[0] >= 0)
    detail += "; least critical distortion γ* ≈ " + as_printed(c.least_critical) + ", " + pair_text(c.least_tetrahedra);
  if (c.cospherical) detail += "; " + std::to_string(c.cospherical) + " exactly cospherical in a vertex's metric";
  if (c.decided) {
    detail += "; " + std::to_string(c.quasi_cospherical) + " γ₀-cospherical for γ₀ = " + excerpt(b.gamma0);
    if (c.at_boundary) detail += ", " + std::to_string(c.at_boundary) + " exactly at γ₀";
    if (c.quasi_cospherical) detail += ", least radius-edge ratio of those ≈ " + as_printed(c.least_radius_edge) + " (" + pair_text(c.least_radius_edge_tetrahedra) + ")";
  }
  if (c.unmeasured) detail += "; " + std::to_string(c.unmeasured) + " beyond the doubles, γ* not measured";
  detail += ")";
  const bool least = c.least_tetrahedra[0] >= 0, radius = c.decided && c.quasi_cospherical;
  v.checks.push_back({"quasi_cosphericity", "LU's sliver measure (quasi-cosphericity of tetrahedra sharing a face, Definitions 3.6 and 3.9)",
                      "slivers", true, false, detail, "", {texts(c.witnesses)},
                      {{"configurations", c.configurations}, {"cospherical", c.cospherical},
                       {"least_critical_distortion", least ? ReportJson(c.least_critical) : ReportJson(nullptr)},
                       {"least_critical_tetrahedra", least ? pair(c.least_tetrahedra) : ReportJson(nullptr)},
                       {"gamma0", c.decided ? ReportJson(b.gamma0) : ReportJson(nullptr)},
                       {"quasi_cospherical", c.decided ? ReportJson(c.quasi_cospherical) : ReportJson(nullptr)},
                       {"at_boundary", c.decided ? ReportJson(c.at_boundary) : ReportJson(nullptr)},
                       {"least_radius_edge", radius ? ReportJson(c.least_radius_edge) : ReportJson(nullptr)},
                       {"least_radius_edge_tetrahedra", radius ? pair(c.least_radius_edge_tetrahedra) : ReportJson(nullptr)},
                       {"unmeasured", c.unmeasured}}});
}

// UGAWG's measures (oracle/certify/ugawg_measures.hpp): statistics, never a verdict.
void add_ugawg3(const oracle::UgawgMeasures& u, CertifyVerdict& v) {
  ReportJson bins = ReportJson::array();
  for (std::size_t b : u.quality_bins) bins.push_back(b);
  v.checks.push_back({"ugawg", "UGAWG's measures, in floating point", "UGAWG", true, false,
                      " (log-interpolated edge lengths: " + percent(u.unit_edges, u.edges) + " in [1/√2, √2], " + as_printed(u.shortest) + " to " +
                          as_printed(u.longest) + ", mean " + as_printed(u.mean_length) + "; Omega_h quality: least " + as_printed(u.least_quality) +
                          " at tetrahedron " + std::to_string(u.least_tetrahedron) + ", mean " + as_printed(u.mean_quality) +
                          (u.unmeasured ? "; " + std::to_string(u.unmeasured) + " beyond the doubles, not measured" : "") + ")",
                      " (" + percent(u.unit_edges, u.edges) + " unit)", {},
                      {{"edges", u.edges}, {"unit_edges", u.unit_edges}, {"shortest", u.shortest}, {"longest", u.longest},
                       {"mean_length", u.mean_length}, {"tetrahedra", u.tetrahedra}, {"least_quality", u.least_quality},
                       {"least_tetrahedron", u.least_tetrahedron}, {"mean_quality", u.mean_quality}, {"quality_bins", bins}, {"unmeasured", u.unmeasured}}});
}

}  // namespace

CertifyVerdict certify_verdict(const oracle::Certify3Report& r, const oracle::Certify3Options& o, const geometry::Mesh3<Rational>& mesh,
                               const BoundTexts& b) {
  CertifyVerdict v;
  v.dimension = 3;
  v.vertices = mesh.vertices.size(), v.triangles = mesh.tetrahedra.size(), v.holds = r.holds(o);
  v.described_witnesses = o.described_witnesses;
  v.has_metrics = mesh.metrics.size() == mesh.vertices.size() && !mesh.metrics.empty();
  if (r.valid) add_validity3(r, v);
  if (r.uniform_checked) add_uniform3(r, v);
  if (o.rho0 && v.has_metrics) add_radius_edge(r.worst_rho, r.worst_rho_tetrahedron, r.worst_rho_vertex, r.rho_violations, b, v, "tetrahedron");
  if (o.gamma0 && v.has_metrics) add_distortion(r.worst_gamma, r.worst_gamma_tetrahedron, r.gamma_violations, b, v, "tetrahedron");
  if (r.cosphericity) add_cosphericity3(*r.cosphericity, b, v);
  if (r.lengths) add_lengths(*r.lengths, b, v);
  if (r.quality) add_quality(*r.quality, b, v, "tetrahedron");
  if (r.angles) add_angles(*r.angles, b, v, "tetrahedron");
  if (r.ugawg) add_ugawg3(*r.ugawg, v);
  return v;
}

CertifyVerdict certify_verdict(const oracle::CertifyReport& r, const oracle::CertifyOptions& o,
                               const geometry::Mesh<Rational>& mesh, const BoundTexts& b) {
  CertifyVerdict v;
  v.vertices = mesh.sites.size(), v.triangles = mesh.triangles.size(), v.holds = r.holds(o);
  v.described_witnesses = o.described_witnesses;
  v.has_metrics = mesh.metrics.size() == mesh.sites.size();
  if (r.valid) add_validity(r, v);
  if (r.uniform_checked) add_uniform(r, v);
  if (o.rho0 && v.has_metrics) add_radius_edge(r.worst_rho, r.worst_rho_triangle, r.worst_rho_vertex, r.rho_violations, b, v);
  if (o.gamma0 && v.has_metrics) add_distortion(r.worst_gamma, r.worst_gamma_triangle, r.gamma_violations, b, v);
  if (r.lengths) add_lengths(*r.lengths, b, v);
  if (r.quality) add_quality(*r.quality, b, v);
  if (r.angles) add_angles(*r.angles, b, v);
  return v;
}

std::string full_text(const CertifyVerdict& v, const std::string& input) {
  std::ostringstream o;
  o << input << ": " << v.vertices << " vertices, " << v.triangles << (v.dimension == 3 ? " tetrahedra" : " triangles");
  if (!v.metric_source.empty()) o << ", metrics from " << v.metric_source;
  o << "\n";
  for (const CheckReport& c : v.checks) {
    o << "  " << c.title << ": " << verdict(c) << c.detail << "\n";
    for (const WitnessLines& lines : c.witnesses) {
      for (const std::string& line : lines.first) o << "    " << line << "\n";
      if (lines.count > lines.first.size()) o << "    … and " << lines.count - lines.first.size() << " more\n";
    }
  }
  if (!v.has_metrics) o << "  no metric: only validity was checked (the other checks need a metric at every vertex)\n";
  if (!v.holds)
    o << "  (witnesses number vertices, " << (v.dimension == 3 ? "tetrahedra" : "triangles") << " and edges from 0, in the order of the file)\n";
  o << (v.holds ? "certified\n" : "not certified\n");
  return o.str();
}

std::string one_line(const CertifyVerdict& v) {
  std::string s = "certify (exact): ";
  for (std::size_t i = 0; i < v.checks.size(); ++i)
    s += (i ? ", " : "") + v.checks[i].short_title + " " + verdict(v.checks[i]) + v.checks[i].short_detail;
  return s + ": " + (v.holds ? "certified" : "NOT certified") + "\n";
}

namespace {

// A list of the report streamed into --json: its key, how many entries are written, and how one is.
struct StreamedList {
  const char* key;
  std::size_t size;
  std::function<ReportJson(std::size_t)> entry;
};

// `element`: what WitnessPlace::triangle numbers ("triangle", or "tetrahedron" in 3D).
StreamedList witness_list(const char* key, const oracle::WitnessList& ws, const char* element = "triangle") {
  return {key, ws.described().size(), [&ws, element](std::size_t i) {
            const oracle::MeshWitness& w = ws.described()[i];
            return ReportJson{{"vertex", w.vertex}, {element, w.triangle}, {"site", w.site}, {"text", w.text}};
          }};
}

template <class T>
StreamedList first_of(const char* key, const std::vector<T>& list, std::size_t limit) {
  return {key, std::min(limit, list.size()), [&list](std::size_t i) { return ReportJson(list[i]); }};
}

// The lists of check `key`, after its other fields.
std::vector<StreamedList> lists_of(const std::string& key, const oracle::CertifyReport& r, std::size_t limit) {
  if (key == "valid")
    return {first_of("failures", r.valid->failures, limit), first_of("bad_triangles", r.valid->bad_cells, limit),
            first_of("bad_edges", r.valid->bad_edges, limit), first_of("segment_failures", r.segment_failures, limit)};
  if (key == "locally_uniform") return {witness_list("violations", r.uniform_violations), witness_list("ties", r.uniform_ties)};
  if (key == "radius_edge") return {witness_list("violations", r.rho_violations)};
  if (key == "distortion") return {witness_list("violations", r.gamma_violations)};
  if (key == "lengths") return {witness_list("violations", r.lengths->range_violations)};
  if (key == "quality") return {witness_list("violations", r.quality->violations)};
  if (key == "angles")
    return {witness_list("violations", r.angles->violations), first_of("undecided_triangles", r.angles->undecided_triangles, limit)};
  return {};
}

std::vector<StreamedList> lists_of(const std::string& key, const oracle::Certify3Report& r, std::size_t limit) {
  if (key == "valid") return {first_of("failures", r.valid->failures, limit), first_of("bad_tetrahedra", r.valid->bad_tetrahedra, limit)};
  if (key == "locally_uniform")
    return {witness_list("violations", r.uniform_violations, "tetrahedron"), witness_list("ties", r.uniform_ties, "tetrahedron")};
  if (key == "lengths") return {witness_list("violations", r.lengths->range_violations)};
  if (key == "quality") return {witness_list("violations", r.quality->violations, "tetrahedron")};
  if (key == "angles") return {witness_list("violations", r.angles->violations, "tetrahedron")};
  if (key == "radius_edge") return {witness_list("violations", r.rho_violations, "tetrahedron")};
  if (key == "distortion") return {witness_list("violations", r.gamma_violations, "tetrahedron")};
  if (key == "quasi_cosphericity") {  // a witness: the vertex whose metric, the two tetrahedra
    const oracle::WitnessList& ws = r.cosphericity->witnesses;
    return {{"witnesses", ws.described().size(), [&ws](std::size_t i) {
               const oracle::MeshWitness& w = ws.described()[i];
               return ReportJson{{"vertex", w.vertex}, {"tetrahedra", ReportJson::array({w.triangle, w.site})}, {"text", w.text}};
             }}};
  }
  return {};
}

void indent(std::ostream& out, int n) {
  for (int i = 0; i < n; ++i) out << ' ';
}

// v as nlohmann's dump(2) lays it out, at the given indentation.
void write_pretty(std::ostream& out, const ReportJson& v, int at) {
  if (v.is_structured() && !v.empty()) {
    out << (v.is_object() ? "{\n" : "[\n");
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (it != v.begin()) out << ",\n";
      indent(out, at + 2);
      if (v.is_object()) out << ReportJson(it.key()).dump() << ": ";
      write_pretty(out, it.value(), at + 2);
    }
    out << "\n";
    indent(out, at);
    out << (v.is_object() ? "}" : "]");
  } else {
    out << v.dump();
  }
}

// An object: its fields, then its lists, one entry a line.
void write_object(std::ostream& out, const ReportJson& fields, const std::vector<StreamedList>& lists, int at) {
  out << "{";
  const char* separator = "\n";
  for (auto it = fields.begin(); it != fields.end(); ++it) {
    out << separator;
    indent(out, at + 2);
    out << ReportJson(it.key()).dump() << ": ";
    write_pretty(out, it.value(), at + 2);
    separator = ",\n";
  }
  for (const StreamedList& l : lists) {
    out << separator;
    indent(out, at + 2);
    out << ReportJson(l.key).dump() << ": [";
    for (std::size_t i = 0; i < l.size; ++i) {
      out << (i ? ",\n" : "\n");
      indent(out, at + 4);
      out << l.entry(i).dump();
    }
    if (l.size > 0) {
      out << "\n";
      indent(out, at + 2);
    }
    out << "]";
    separator = ",\n";
  }
  out << "\n";
  indent(out, at);
  out << "}";
}

// The --json report of either dimension: the top-level fields, then each check with its lists.
template <class Report>
void write_report_json(std::ostream& out, const CertifyVerdict& v, const Report& r) {
  const std::size_t limit = v.described_witnesses;
  ReportJson top{{"holds", v.holds}, {"dimension", v.dimension}, {"vertices", v.vertices}};
  top[v.dimension == 3 ? "tetrahedra" : "triangles"] = v.triangles;
  top["has_metrics"] = v.has_metrics;
  top["metric_source"] = v.metric_source;
  top["indices_from"] = 0;
  top["witnesses_listed"] = limit == oracle::all_witnesses ? ReportJson(nullptr) : ReportJson(limit);
  // The checks as fields of the top level, each written with its lists (one witness per triangle
  // at most, the first `limit` of them) from the report itself.
  out << "{";
  const char* separator = "\n";
  for (auto it = top.begin(); it != top.end(); ++it) {
    out << separator << "  " << ReportJson(it.key()).dump() << ": ";
    write_pretty(out, it.value(), 2);
    separator = ",\n";
  }
  for (const CheckReport& c : v.checks) {
    out << separator << "  " << ReportJson(c.key).dump() << ": ";
    write_object(out, c.json, lists_of(c.key, r, limit), 2);
  }
  out << "\n}\n";
}

}  // namespace

void write_json(std::ostream& out, const CertifyVerdict& v, const oracle::CertifyReport& r) { write_report_json(out, v, r); }
void write_json(std::ostream& out, const CertifyVerdict& v, const oracle::Certify3Report& r) { write_report_json(out, v, r); }

RunCertificate3 certify_run3(const geometry::Mesh3<Rational>& mesh, double rho0, double gamma0, int threads, const std::string& metric_source) {
  oracle::Certify3Options o;
  o.rho0 = rational_from_double(rho0), o.gamma0 = rational_from_double(gamma0), o.threads = threads;
  o.metric = true;  // edge lengths, quality, dihedral angles and UGAWG's measures: measured, no bound
  RunCertificate3 c{oracle::certify_mesh3(mesh, o), {}};
  BoundTexts bounds;
  bounds.rho0 = as_printed(rho0), bounds.gamma0 = as_printed(gamma0);
  c.verdict = certify_verdict(c.report, o, mesh, bounds);
  c.verdict.metric_source = metric_source;
  return c;
}

}  // namespace anisocert::io
