#pragma once
// The metric checks of a mesh from elsewhere (what MMG, BAMG and the UGAWG benchmarks judge an
// adapted mesh by), each decided exactly per edge or triangle, with interval enclosures first:
//  - lengths: the length of edge ab in the metric of each endpoint, ℓ_v² = (b − a)ᵀ M_v (b − a),
//    a rational; an edge is a unit edge when both lengths lie in [1/√2, √2] (ℓ² in [1/2, 2]);
//    a length range [lo, hi] is a verdict on every length;
//  - quality: the mean ratio of triangle T in metric M, q = 4√3 area_M(T) / Σ ℓ_M² (1 for the
//    equilateral triangle in M), with area_M = √det M · area; the triangle's quality is the least
//    over its vertices' metrics; enclosed in intervals (it is irrational); q >= q₀ is decided as
//    12 det(M) D² >= q₀² S² with D twice the area and S = Σ ℓ_M², rationals;
//  - angles: the angle of each corner in the metric of its vertex (LS §2's angle "measured from the
//    perspective of" a point) against a lower bound θ in degrees (0 < θ <= 90), decided as
//    sin² angle >= sin² θ or the angle obtuse (predicates/angle.hpp), against rational bounds of
//    sin² θ (exact for θ = 30°, 45°, 60°, 90°; else MPFI enclosures refined until they decide).
// Triangles that are flat or clockwise are not measured (validity reports them); they are counted
// as undecided.
#include "oracle/certify/enclosed_mesh.hpp"
#include "oracle/certify/witness_list.hpp"

#include <optional>
#include <string>
#include <vector>

namespace anisocert::oracle {

struct LengthReport {
  std::size_t edges = 0, unit_edges = 0;   // unit: both lengths in [1/√2, √2], decided exactly
  double shortest = 0, longest = 0;        // approximate extreme lengths over both metrics
  int shortest_edge = -1, longest_edge = -1;
  std::vector<double> lengths;             // approximate, two per edge (for the histogram)
  WitnessList range_violations;            // one per edge outside the range (when given): vertex, -1, other end
};

struct QualityReport {
  std::size_t measured = 0, undecided = 0;
  FilterInterval worst{1, 1};               // encloses the least quality
  int worst_triangle = -1;
  std::vector<std::pair<double, FilterInterval>> quantiles;  // (p, enclosure of the p-quantile)
  std::vector<double> qualities;            // approximate, one per measured triangle
  WitnessList violations;                   // one per triangle below q₀ (when given)
};

struct AngleReport {
  std::size_t measured = 0, undecided = 0;
  double smallest = 180, largest = 0;       // approximate, degrees
  int smallest_triangle = -1, largest_triangle = -1;   // (or tetrahedron)
  std::vector<double> element_smallest;    // each measured element's smallest angle, approximate (for the histogram)
  WitnessList violations;                   // one per element with an angle below θ (when given)
  std::vector<int> undecided_triangles;     // θ's bounds never decided (not seen in practice)
};

// `described`: how many witnesses of each list are described in full (witness_list.hpp); all are
// counted.
LengthReport check_lengths(const EnclosedMesh& m, const std::vector<std::pair<int, int>>& edges,
                           const std::optional<std::pair<Rational, Rational>>& range, std::size_t described = all_witnesses);
// The same for a tetrahedral mesh (issue 39).
LengthReport check_lengths(const EnclosedMesh3& m, const std::vector<std::pair<int, int>>& edges,
                           const std::optional<std::pair<Rational, Rational>>& range, std::size_t described = all_witnesses);
QualityReport check_quality(const EnclosedMesh& m, const std::optional<Rational>& min_quality,
                            std::size_t described = all_witnesses);
// The same for tetrahedra (issue 39): 12 (3 V_M)^(2/3) / Σ ℓ_M², 1 for the regular tetrahedron,
// decided against q₀ by 432 det(M) D² ≥ q₀³ S³ exactly; flat tetrahedra not measured.
QualityReport check_quality(const EnclosedMesh3& m, const std::optional<Rational>& min_quality,
                            std::size_t described = all_witnesses);
AngleReport check_angles(const EnclosedMesh& m, const std::optional<Rational>& min_angle_degrees,
                         std::size_t described = all_witnesses);
// The same for tetrahedra (issue 39): the dihedral angle at each edge in each end's metric
// (predicates/dihedral.hpp), the smallest and largest measured, flat tetrahedra not measured.
AngleReport check_angles(const EnclosedMesh3& m, const std::optional<Rational>& min_angle_degrees,
                         std::size_t described = all_witnesses);

// Rational bounds lo <= sin²(θ°) <= hi for 0 < θ <= 90: equal and exact where sin² θ is rational
// (θ = 30°, 45°, 60°, 90°: by Niven's theorem the only rational-degree angles in (0°, 90°] with
// cos 2θ rational), else an MPFI enclosure at prec bits.
std::pair<Rational, Rational> sin_squared_bounds(const Rational& degrees, long prec);

}  // namespace anisocert::oracle
