#include "io/reports/dual_report.hpp"

#include "io/diagram_json.hpp"
#include "io/reports/printed.hpp"
#include "io/svg/canvas.hpp"

#include <sstream>

namespace anisocert::io {
namespace {

std::string owners_text(const std::vector<int>& sites) {
  std::string s;
  for (int v : sites) s += (s.empty() ? "" : ", ") + std::to_string(v);
  return "(" + s + ")";
}

}  // namespace

std::string dual_text(const oracle::Diagram& d, const oracle::MeshDual& m, const std::string& input, const std::string& metric_source) {
  const std::size_t n = m.kinds.size();
  const DiagramCounts c = diagram_counts(d);
  std::ostringstream o;
  o << input << ": " << d.input.sites.size() << " vertices, " << n << " triangles, metrics from " << metric_source
    << "; D|Ω of its vertices, Ω its boundary (" << d.input.domain.size() << " corners)\n"
    << "  triangles dual to a Voronoi vertex: " << m.dual << " (" << percent(m.dual, n) << "), ties (three owners of a vertex with more): "
    << m.ties << ", not dual: " << m.not_dual << " (" << percent(m.not_dual, n) << ")\n";
  for (std::size_t k = 0; k < m.not_dual_witnesses.size() && k < 3; ++k)
    o << "    triangle " << m.not_dual_witnesses[k].triangle << ": " << m.not_dual_witnesses[k].why << "\n";
  if (m.not_dual > 3) o << "    … and " << m.not_dual - 3 << " more\n";
  o << "  dual triangles of D|Ω that are not triangles of the mesh: " << m.missing_count << " of " << d.dual_triangles.size() << "\n";
  for (std::size_t k = 0; k < m.missing.size() && k < 3; ++k)
    o << "    Voronoi vertex " << m.missing[k].vertex << " owned by " << owners_text(m.missing[k].sites) << "\n";
  if (m.missing_count > 3) o << "    … and " << m.missing_count - 3 << " more\n";
  o << "  D|Ω: " << c.voronoi_vertices << " Voronoi vertices, " << c.arcs << " arcs, " << c.orphans << " orphans, " << c.unwedged_arcs
    << " unwedged arcs, " << c.unwedged_vertices << " unwedged vertices; its dual "
    << (d.dual_check.is_triangulation ? "is a triangulation of Ω" : "is not a triangulation of Ω") << "\n"
    << "  Theorem 7 preconditions: " << (d.theorem7.preconditions_hold ? "hold" : "do not hold");
  if (!d.theorem7.reasons.empty()) o << " (" << d.theorem7.reasons.front() << (d.theorem7.reasons.size() > 1 ? ", …" : "") << ")";
  if (d.theorem7.preconditions_hold) o << "; conclusion " << (d.dual_check.is_triangulation ? "confirmed" : "CONTRADICTED");
  o << "\n  (triangles and vertices numbered from 0 in the order of the file; Voronoi vertices as in --json)\n"
    << (m.is_dual() ? "the mesh is the dual of the anisotropic Voronoi diagram of its vertices\n"
                    : "the mesh is not the dual of the anisotropic Voronoi diagram of its vertices\n");
  return o.str();
}

nlohmann::ordered_json dual_json(const oracle::Diagram& d, const oracle::MeshDual& m, const std::string& metric_source) {
  using J = nlohmann::ordered_json;
  const DiagramCounts c = diagram_counts(d);
  J not_dual = J::array(), missing = J::array(), reasons = J::array();
  for (const auto& x : m.not_dual_witnesses) not_dual.push_back({{"triangle", x.triangle}, {"why", x.why}});
  for (const auto& x : m.missing) missing.push_back({{"voronoi_vertex", x.vertex}, {"sites", x.sites}});
  for (std::size_t k = 0; k < d.theorem7.reasons.size() && k < m.described; ++k) reasons.push_back(d.theorem7.reasons[k]);
  return {{"is_dual", m.is_dual()},
          {"input", {{"vertices", d.input.sites.size()}, {"triangles", m.kinds.size()}, {"domain_corners", d.input.domain.size()},
                     {"metric_source", metric_source}}},
          {"triangles", {{"dual", m.dual}, {"ties", m.ties}, {"not_dual", m.not_dual}}},
          {"not_dual", {{"count", m.not_dual}, {"first", not_dual}}},
          {"missing", {{"count", m.missing_count}, {"first", missing}}},
          {"diagram", {{"voronoi_vertices", c.voronoi_vertices}, {"arcs", c.arcs}, {"faces", c.faces}, {"orphans", c.orphans},
                       {"unwedged_arcs", c.unwedged_arcs}, {"unwedged_vertices", c.unwedged_vertices}, {"dual_triangles", d.dual_triangles.size()},
                       {"dual_polygons", d.dual_polygons.size()}, {"dual_is_triangulation", d.dual_check.is_triangulation}}},
          {"theorem7", {{"preconditions_hold", d.theorem7.preconditions_hold}, {"reasons_count", d.theorem7.reasons.size()},
                        {"reasons", reasons}, {"disagreement", d.theorem7.disagreement}}},
          {"seconds", d.stats.seconds_candidates + d.stats.seconds_vertices + d.stats.seconds_arcs + d.stats.seconds_faces +
                          d.stats.seconds_dual}};
}

std::string dual_svg(const geometry::Mesh<Rational>& mesh, const oracle::Diagram& d, const oracle::MeshDual& m, const std::string& caption) {
  std::vector<predicates::Point2<double>> p;
  for (const auto& s : mesh.sites) p.push_back({s.x.convert_to<double>(), s.y.convert_to<double>()});
  const Canvas c(geometry::Polygon<double>(p.begin(), p.end()), 0.03);
  std::ostringstream o;
  o.precision(6);
  c.open(o, 80, 560);
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const auto path = [&](const int* t) {
    o << "M" << c.X(p[t[0]].x) << " " << c.Y(p[t[0]].y) << " L" << c.X(p[t[1]].x) << " " << c.Y(p[t[1]].y) << " L" << c.X(p[t[2]].x)
      << " " << c.Y(p[t[2]].y) << " Z";
  };
  // Dual triangles pale, ties yellow, triangles not dual red; the missing dual triangles outlined in blue.
  const std::array<const char*, 3> fill{"#eef3fb", "#f5d142", "#e04030"};
  for (int kind = 0; kind < 3; ++kind) {
    o << "<path fill=\"" << fill[kind] << "\" stroke=\"#1f4e9c\" stroke-width=\"0.3\" d=\"";
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (static_cast<int>(m.kinds[t]) == kind) path(mesh.triangles[t].data());
    o << "\"/>\n";
  }
  o << "<path fill=\"none\" stroke=\"#0050ff\" stroke-width=\"1.2\" d=\"";
  for (const auto& cell : m.missing) path(cell.sites.data());
  const double y = c.height();
  o << "\"/>\n<g font-family=\"sans-serif\" font-size=\"12\"><text x=\"10\" y=\"" << y + 20 << "\">" << xml_text(caption) << "</text>\n"
    << "<text x=\"10\" y=\"" << y + 40 << "\">pale: dual to a Voronoi vertex (" << m.dual << "); red: not dual (" << m.not_dual << "); yellow: ties ("
    << m.ties << ")</text>\n<text x=\"10\" y=\"" << y + 60 << "\">blue outline: dual triangles missing from the mesh (" << m.missing_count
    << " of the diagram's " << d.dual_triangles.size() << "; the first " << m.missing.size() << " drawn)</text></g>\n</svg>\n";
  return o.str();
}

}  // namespace anisocert::io
