#pragma once
// LS §9's rules as the LS refiner implements them, in priority order (a lower number first): the
// rule numbers of the trace and the names of the report come from here.
//   1 encroached segment: a subsegment that meets the cell of a site other than its endpoints is
//     split in that cell, as near its "midpoint" as possible (segment_cells.hpp);
//   2 violator encroaches: a violator that would encroach a subsegment is not inserted; the
//     subsegment is split in the cell the violator would have had ("A new site is never permitted
//     to encroach upon a segment");
//   3 poor angle: a Voronoi vertex in Ω whose dual triangle has an angle below θ_bound in the
//     metric gets a site, unless the triangle lies across a small input angle (its shortest edge
//     joins two segments that meet at less than 60°, on one shell: common/corner_shells.hpp; the
//     report counts those left);
//   4 too large: likewise when the triangle's circumradius in the metric exceeds `size`;
//   5 inverted: a Voronoi vertex in Ω whose dual triangle is inverted (its sites' order around the
//     vertex the reverse of their order around the triangle) gets a site (before rules 3 and 4);
//   6 island: a site whose cell holds no Voronoi vertex (its cell, or part of it, is bounded by an
//     ellipse, LS §9's "arcs that are ellipses") gets a site on that bisector (last);
//   7 unwedged: a Voronoi vertex in Ω outside wedge(v, w) of two of its sites (LS Definitions 2–3:
//     a wedge violator, since the vertex lies on the arc of v and w) gets a site (after rule 5);
//   8 tie: where the diagram is unresolved in Ω (a vertex of degree 4 or more among different
//     metrics, which symmetric fields give: its dual is no triangle), a site, before the other
//     violators. Not LS §9's rule; ties among sites of one metric are kept exactly instead
//     (exact_tie.hpp) and judged by rules 3 and 4.
//   9 corner shell: before every other rule, each vertex of X where two segments meet at less than
//     60° in its metric gets a site on all its subsegments at one power-of-two distance in that
//     metric (Ruppert's corner lopping, common/corner_shells.hpp, on both paths); later splits of a
//     subsegment with one end at such a vertex go on the next shell, in whichever cell.
// Rules 5 to 8 cannot fire while every site has one metric (delaunay_in_metric.hpp): every arc
// lies in its wedge, and the dual of every Voronoi vertex is a counter-clockwise triangle, or a
// convex polygon of cocircular sites split into such triangles.
#include "refiners/common/run_record.hpp"

#include <array>
#include <vector>

namespace anisocert::refiners::ls {

enum class Rule {
  none = 0,
  encroached_segment = 1,
  violator_encroaches = 2,
  poor_angle = 3,
  too_large = 4,
  inverted = 5,
  island = 6,
  unwedged = 7,
  tie = 8,
  corner_shell = 9
};
inline constexpr std::array<Rule, 9> rules_by_priority{Rule::corner_shell, Rule::encroached_segment, Rule::violator_encroaches, Rule::tie, Rule::inverted,
                                                       Rule::unwedged, Rule::poor_angle, Rule::too_large, Rule::island};

inline const char* rule_name(Rule rule) {
  switch (rule) {
    case Rule::encroached_segment: return "encroached segment";
    case Rule::violator_encroaches: return "violator encroaches";
    case Rule::poor_angle: return "poor angle";
    case Rule::too_large: return "too large";
    case Rule::inverted: return "inverted";
    case Rule::island: return "island";
    case Rule::unwedged: return "unwedged";
    case Rule::tie: return "tie";
    case Rule::corner_shell: return "corner shell";
    case Rule::none: break;
  }
  return "none";
}

// The rules in priority order, numbered and named for the run's record.
inline std::vector<common::RuleName> rule_table() {
  std::vector<common::RuleName> table;
  for (Rule rule : rules_by_priority) table.push_back({static_cast<int>(rule), rule_name(rule)});
  return table;
}

}  // namespace anisocert::refiners::ls
