#pragma once
// What every refiner returns (DESIGN.md § Layers, refiners/): the mesh in the one mesh shape, how
// the run stopped, and what it did, rule by rule and insertion by insertion.
#include "geometry/mesh.hpp"
#include "geometry/mesh3.hpp"

#include <string>
#include <utility>
#include <vector>

namespace anisocert::refiners::common {

// The budgets every run has (DESIGN.md non-negotiable 5: long work has budgets and says what it
// did when it stops).
struct Budget {
  std::size_t max_vertices = 200000;
  double max_seconds = 120;
};

// One insertion, for the properties on traces (LU Lemmas 4.1–4.4, LS Theorem 11, BWY §4.2): where,
// by which rule (its number in the refiner's rule table), and its distance to the nearest earlier
// site in the new site's metric. For a rule acting on an element at a site (LU: a triangle of the
// star of `site`), that site and the element's circumradius in its metric. A point that stands
// for an exact one it rounds (a Voronoi vertex) is within `displacement` of it (Euclidean, from
// above; 0 when the rule's point is the inserted one). A split made instead of inserting another
// rule's point (LS §9: "A new site is never permitted to encroach upon a segment") names that rule
// in `for_rule` (0 otherwise).
struct Insertion {
  int rule;
  double x, y;
  double nearest_distance;
  int site = -1;
  double radius = 0;
  double displacement = 0;
  int for_rule = 0;
};

// How a run ended and what it did, in any dimension.
struct RunOutcome {
  // The run finished (no rule applies anywhere: not stopped by a budget or a stall) and the
  // refiner's output condition holds (star sets: every star simplex is in its vertices' stars).
  bool consistent = false;
  std::string stop_reason;      // that condition's name, the budget that stopped it, or why it cannot go on
  std::string last_rule = "none";                            // the rule of the last insertion (a stall may be another's)
  std::vector<std::pair<std::string, std::size_t>> rule_counts;  // insertions per rule, in priority order
  double seconds = 0;
};

struct RefineResult : RunOutcome {
  geometry::Mesh<double> mesh;
  std::vector<Insertion> trace;
};

// One insertion of a 3D run (issue 40), for the properties on traces: the point, the rule's
// number, and for rules 2–5 the site whose star's tetrahedron was refined and that tetrahedron's
// circumradius in its metric. `stand_in`: the tetrahedron's centroid, inserted because the point
// picked lay outside Ω and encroached nothing (not LU's Refine(τ), so not bound by its lemmas).
struct Insertion3 {
  int rule;
  predicates::Point3<double> p;
  int site = -1;
  double radius = 0;
  bool stand_in = false;
};

// A 3D run (issue 40): the tetrahedral mesh, its boundary triangles declared.
struct RefineResult3 : RunOutcome {
  geometry::Mesh3<double> mesh;
  std::vector<Insertion3> trace;  // the insertions after Ω's vertices and the interior seeds, in order
};

}  // namespace anisocert::refiners::common
