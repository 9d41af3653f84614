#pragma once
// Locally uniform anisotropic meshing with stars in 2D (Boissonnat, Wormser & Yvinec, LU §3–§4):
// every site v keeps its star S_v, the triangles incident to v in Del_{M_v}(V) restricted to Ω,
// recomputed only when a new site falls in its conflict zone Z_v (LU Lemma 3.5). Stars are
// refined by the rules of LU §4.1 in priority order until they are consistent, then merged:
//   1 encroachment: a boundary subsegment with a site inside its diametral ellipse (in the site's
//     or the endpoints' metric; LU Definition 3.16) is split at its midpoint;
//   2 distortion: a triangle whose vertices' metrics differ by τ ≥ γ₀ (the vertex-pair distortion
//     stands in for LU's total distortion over the circumballs);
//   3 radius-edge ratio > ρ₀ in M_v;
//   4 size: circumradius in M_v > `size` (so that the mesh fits the field);
//   5 inconsistency: an edge vw in S_v but not in S_w (LU Definition 3.3).
// Refine(τ) picks a random point in the picking region B_{M_v}(c, δr), discarded while it would
// form a forbidden γ₀-cocircular configuration (Pick_valid, LU Definition 3.6), and
// Insert_or_snap splits the boundary subsegment it would encroach instead. Floating point throughout, with exact filtered predicates for every combinatorial
// decision (in-circle, orientation, distance comparisons), so stars never disagree by rounding.
// The refiners never include the oracle (DESIGN.md § Layers); the exact certifier judges the output.
#include "refiners/star/metric_field.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace anisocert::refiners::star {

struct RefineParameters {
  double rho0 = 3, gamma0 = 1.5, delta = 0.1, beta = 3, size = 1;
  // Pick_valid: how many picked points may be discarded as γ₀-cocircular before one is kept
  // (0 turns the test off). The test is only selective for γ₀ near 1, as LU Theorem 4.5 assumes.
  int pick_attempts = 3;
  std::size_t max_vertices = 200000;
  double max_seconds = 120;
  unsigned seed = 1;
};

enum Rule { encroachment = 1, distortion = 2, radius_edge = 3, size = 4, inconsistency = 5 };
const char* rule_name(int rule);

// One insertion, for the LU Lemma 4.1–4.4 properties: where, by which rule, and its distance to
// the nearest earlier site in the new site's metric.
struct Insertion {
  int rule;
  double x, y;
  double nearest_distance;
  // For rules 2–5: the star whose triangle τ was refined, and τ's circumradius r in its metric;
  // the point lies in B_{M_v}(c, δr), so every earlier site is at M_v-distance ≥ (1 − δ) r.
  int star = -1;
  double radius = 0;
};

struct RefineResult {
  std::vector<predicates::Point2<double>> sites;
  std::vector<predicates::Sym2<double>> metrics;
  std::vector<predicates::Point2<double>> domain;
  std::vector<std::pair<int, int>> segments;   // boundary subsegments, by site index
  std::vector<std::array<int, 3>> triangles;   // merged from consistent stars, counter-clockwise
  bool consistent = false;                     // every star triangle is in the stars of its three vertices
  std::string stop_reason;                     // "all stars consistent", the budget that stopped it, or why it cannot go on
  int last_rule = 0;                           // the rule still firing when a budget stopped it
  std::size_t inconsistent_triangles = 0;
  // LU Lemma 4.1 (rule 1 ends) needs every boundary angle > 90° in the metric; the corners of Ω
  // where the angle in the corner's metric is not (e₁ᵀ M e₂ ≥ 0 for the two edge directions).
  std::vector<int> acute_corners;
  std::array<std::size_t, 6> rule_counts{};
  // Pick_valid: points discarded as γ₀-cocircular, and refinements that kept a forbidden point.
  std::size_t picks_rejected = 0, picks_exhausted = 0;
  std::size_t refinements = 0;  // calls of Refine(τ) (rules 2–5), whatever they inserted or split
  double seconds = 0;
  std::vector<Insertion> trace;
};

// `domain`: a simple counter-clockwise polygon (its edges are the constrained segments).
RefineResult refine_star(const std::vector<predicates::Point2<double>>& domain, const MetricField& field,
                         const RefineParameters& p, const std::function<void(const std::string&)>& progress = {});

}  // namespace anisocert::refiners::star
