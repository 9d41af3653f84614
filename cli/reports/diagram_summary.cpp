#include "cli/reports/diagram_summary.hpp"

#include "io/diagram_json.hpp"

#include <sstream>

namespace anisocert::cli {

std::string diagram_summary(const oracle::Diagram& d, const std::string& name) {
  const io::DiagramCounts c = io::diagram_counts(d);
  std::ostringstream o;
  o << name << ": " << d.input.sites.size() << " sites, domain with " << d.input.domain.size() << " corners\n"
    << "  Voronoi vertices " << c.voronoi_vertices << ", arcs " << c.arcs << ", faces " << c.faces << ", orphans "
    << c.orphans << ", wedge violations " << c.wedge_violations << "\n";
  std::size_t closed = 0, cut = 0, high = 0;
  for (const auto& a : d.arcs) closed += a.closed ? 1 : 0, cut += a.cut_by_edges.empty() ? 0 : 1;
  for (const auto& n : d.nodes) high += n.sites.size() > 3 ? 1 : 0;
  o << "  closed arcs " << closed << ", arcs cut by ∂Ω " << cut << ", vertices with more than three owners " << high << "\n";
  std::size_t listed = 0;
  for (std::size_t i = 0; i < d.faces.size(); ++i)
    if (d.faces[i].orphan && listed++ < 5) o << "  orphan: face " << i << " of site " << d.faces[i].site << "\n";
  if (listed > 5) o << "  … and " << listed - 5 << " more orphans (all in --json)\n";
  o << "  dual: " << d.dual_triangles.size() << " triangles, " << d.dual_polygons.size() << " polygons; "
    << (d.dual_check.is_triangulation ? "a triangulation of Ω (checked exactly)" : "not a triangulation of Ω") << "\n";
  for (std::size_t i = 0; i < d.dual_check.failures.size() && i < 3; ++i) o << "    " << d.dual_check.failures[i] << "\n";
  if (d.dual_check.failures.size() > 3) o << "    … and " << d.dual_check.failures.size() - 3 << " more\n";
  o << "  Theorem 7 preconditions: " << (d.theorem7.preconditions_hold ? "hold" : "do not hold") << "\n";
  for (std::size_t i = 0; i < d.theorem7.reasons.size() && i < 3; ++i) o << "    " << d.theorem7.reasons[i] << "\n";
  if (d.theorem7.reasons.size() > 3) o << "    … and " << d.theorem7.reasons.size() - 3 << " more\n";
  if (d.theorem7.preconditions_hold)
    o << "  Theorem 7 conclusion: " << (d.dual_check.is_triangulation ? "confirmed" : "CONTRADICTED") << "\n";
  o << "  time: candidates " << d.stats.seconds_candidates << " s, vertices " << d.stats.seconds_vertices << " s, arcs "
    << d.stats.seconds_arcs << " s, faces " << d.stats.seconds_faces << " s, dual " << d.stats.seconds_dual << " s ("
    << d.stats.threads << (d.stats.threads == 1 ? " thread" : " threads") << (d.stats.exact_only ? ", exact only" : "")
    << ")\n";
  const oracle::FilterCounts& f = d.stats.filters;
  o << "  filters (decided by intervals / exact): roots " << f.roots_filtered << " / " << f.roots_exact << ", samples "
    << f.samples_filtered << " / " << f.samples_exact << ", signs " << f.signs_filtered << " / " << f.signs_exact
    << ", comparisons " << f.comparisons_filtered << " / " << f.comparisons_exact << "; exact points built "
    << f.exact_points << "\n";
  return o.str();
}

}  // namespace anisocert::cli
