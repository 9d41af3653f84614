#pragma once
// BWY §3.2.1's local embedding, judged on T: "non-flat triangles whose vertices are exactly the
// sites, each boundary edge in exactly one, every other edge in two that do not overlap". The
// refiner asks it of its final T (a run whose rules are exhausted must end with a triangulation of
// Ω, BWY Theorem 1's conclusion), and rule 5 (BWY §3.2.2) asks `overlaps` of each vertex's triangle.
#include "predicates/point.hpp"
#include "refiners/bwy/dual_triangles.hpp"

#include <string>
#include <vector>

namespace anisocert::refiners::bwy {

// A subsegment of the PSLG between sites a and b; on_boundary: on an edge of Ω (else interior).
struct Constraint {
  int a, b;
  bool on_boundary;
};

// Rule 5 at triangle t of T: flat, or another triangle on one of its edges has its third vertex on
// t's side of that edge (orientations of the sites, exact).
bool overlaps(const DualTriangles& T, int t, const std::vector<predicates::Point2<double>>& sites);
// The triangles that overlap t so: on one of its edges, their third vertex on t's side of it.
std::vector<int> overlapping(const DualTriangles& T, int t, const std::vector<predicates::Point2<double>>& sites);

// Why T is not a local embedding of the sites with these subsegments, or empty: a flat triangle,
// a site in no triangle, a boundary subsegment not in exactly one triangle or an interior one not
// in two, another edge not in two, or a triangle that overlaps a neighbour (the first found).
std::string embedding_failure(const DualTriangles& T, const std::vector<predicates::Point2<double>>& sites,
                              const std::vector<Constraint>& subsegments);

}  // namespace anisocert::refiners::bwy
