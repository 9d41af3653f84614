#pragma once
// LS §9's rules as the LS refiner implements them, in priority order (a lower number first): the
// rule numbers of the trace and the names of the report come from here.
//   1 encroached segment: a subsegment that meets the cell of a site other than its endpoints is
//     split in that cell, as near its "midpoint" as possible (segment_cells.hpp);
//   2 violator encroaches: a violator that would encroach a subsegment is not inserted; the
//     subsegment is split in the cell the violator would have had ("A new site is never permitted
//     to encroach upon a segment");
//   3 poor angle: a Voronoi vertex in Ω whose dual triangle has an angle below θ_bound in the
//     metric gets a site;
//   4 too large: likewise when the triangle's circumradius in the metric exceeds `size`.
// LS's other violators, wedge violators and vertices with inverted dual triangles, cannot occur
// while every site has one metric (delaunay_in_metric.hpp): every arc lies in its wedge, and the
// dual of every Voronoi vertex is a counter-clockwise triangle.
#include <array>

namespace anisocert::refiners::ls {

enum class Rule { none = 0, encroached_segment = 1, violator_encroaches = 2, poor_angle = 3, too_large = 4 };
inline constexpr std::array<Rule, 4> rules_by_priority{Rule::encroached_segment, Rule::violator_encroaches, Rule::poor_angle,
                                                       Rule::too_large};

inline const char* rule_name(Rule rule) {
  switch (rule) {
    case Rule::encroached_segment: return "encroached segment";
    case Rule::violator_encroaches: return "violator encroaches";
    case Rule::poor_angle: return "poor angle";
    case Rule::too_large: return "too large";
    case Rule::none: break;
  }
  return "none";
}

}  // namespace anisocert::refiners::ls
