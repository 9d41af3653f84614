#pragma once
// BWY §3.2.2's rules as the BWY refiner implements them (the rule numbers of the trace, the names
// of the report). Rule i applies only when no rule j < i does (BWY: "Rule i is applied only if no
// rule j with j < i applies"); the rules the paper does not have come where the table puts them.
//   1 encroached segment: a constrained subsegment e = ab whose segment [a, b] meets the closed cell
//     of a site other than a and b gets a site on e (as LS's rule 1: BWY's applies to those that
//     are no edge of T because they are encroached; splitting every encroached one splits more);
//   2 not an edge: a subsegment, not encroached, that is the edge of no triangle of T (BWY: "because
//     its dual Voronoi edge is a complete ellipse", whose point is to be inserted conditionally)
//     gets a site on e: the point of the ellipse chosen is the one on [a, b] (d_a = d_b), which
//     encroaches e, so the conditional insertion splits e, near that point (split() keeps the
//     coarsest grid double within 1/64 of it). An edge whose Voronoi edge ends outside Ω is no
//     edge of T either, and gets the same site;
//   3 bad shape: a Voronoi vertex v of T with β(v) = r(v)/δ(t_v) > B gets a site at v, r(v) its
//     radius d_a(a, v), δ(t_v) the shortest edge of its triangle, d(p, q) = min(d_p(p, q), d_q(p, q)),
//     unless the triangle lies across a small input angle (its shortest edge joins two segments
//     that meet at less than 60°, on one shell: common/corner_shells.hpp; not BWY's, whose §4
//     assumes no such angle; the report counts those left);
//   4 several vertices: a triangle dual to more than one Voronoi vertex of T gets a site at one;
//   5 overlap: two triangles of T that share an edge and overlap (their third vertices on one side
//     of it) get a site at the Voronoi vertex of one; a flat triangle (three collinear sites) counts
//     as overlapping (BWY §3.2.1 takes T's triangles non-flat);
//   6 too large: a Voronoi vertex of T whose radius exceeds `size` (LS §9's size rule, not BWY's;
//     0: none);
//   7 split instead: the conditional insertion of rules 2–6's point x: "if x encroaches some
//     constrained subsegment e, insert a site on e instead" (the trace names the rule of x);
//   8 island: a site that is a vertex of no triangle of T gets a site on its bisector with its
//     nearest other site (not BWY's: §3.2.1 needs every site in T, and §3.2.2's rules do not
//     provide for one that is not: a site whose cell meets Ω in an island, bounded by an ellipse,
//     has no Voronoi vertex in Ω, encroaches nothing and is in no triangle, so no rule of the
//     paper sees it; regression site-in-no-triangle-left-by-every-rule);
//   9 unresolved: where the diagram is unresolved in Ω (a vertex of degree 4 or more among different
//     metrics: no triangle), a site (not BWY's), before rule 2: T lacks the vertices there, and a
//     subsegment near them would be judged no edge (seen: near-cocircular corners of a rectangle
//     with two metrics of distortion 1.001 got rule 2 splits at half the inter-site distance).
//  10 corner shell: before every other rule, each vertex of X where two segments meet at less than
//     60° in its metric gets a site on all its subsegments at one power-of-two distance in that
//     metric (Ruppert's corner lopping; common/corner_shells.hpp, not BWY's); later splits of a
//     subsegment with one end at such a vertex go on the next shell, in whichever cell.
// A Voronoi vertex of degree k ≥ 4 among sites of one metric (an exact tie, common/exact_tie.hpp) puts a
// fan of its k-gon in T; it is badly shaped when r/δ > B for δ the k-gon's shortest side, which
// every fan has in one triangle (a diagonal of cocircular points is at least the shortest side on
// either side of it).
#include "refiners/common/run_record.hpp"

#include <vector>

namespace anisocert::refiners::bwy {

enum class Rule {
  none = 0,
  encroached_segment = 1,
  not_an_edge = 2,
  bad_shape = 3,
  several_vertices = 4,
  overlap = 5,
  too_large = 6,
  split_instead = 7,
  island = 8,
  unresolved = 9,
  corner_shell = 10
};

inline std::vector<common::RuleName> rule_table() {
  return {{10, "corner shell"}, {1, "encroached segment"}, {9, "unresolved"}, {2, "not an edge"}, {7, "split instead"}, {3, "bad shape"},
          {4, "several vertices"},   {5, "overlap"},     {6, "too large"},     {8, "island"}};
}

inline constexpr int number(Rule r) { return static_cast<int>(r); }

}  // namespace anisocert::refiners::bwy
