#pragma once
// A mesh's exact numbers with their interval enclosures, computed once: the certifier's checks
// decide each predicate on the enclosures first and fall back to the exact rationals only when
// the enclosure cannot decide (predicates::interval_then_exact), so a mesh read from decimal
// text is checked at interval speed with exact answers. The approximations (within one ulp of the
// exact values, and a monotone function of them: equal rationals have equal approximations, and
// order is kept) select candidates (the site tree, the grids) and give the approximate values
// reported beside the verdicts.
#include "geometry/mesh.hpp"
#include "geometry/mesh3.hpp"
#include "numbers/filter_interval.hpp"
#include "oracle/certify/tetrahedron_faces.hpp"

#include <array>
#include <vector>

namespace anisocert::oracle {

struct EnclosedMesh {
  explicit EnclosedMesh(const geometry::Mesh<Rational>& m);

  // The exact orientation of sites a, b, c (interval first).
  Sign orientation(int a, int b, int c) const;

  const geometry::Mesh<Rational>& mesh;
  std::vector<predicates::Point2<FilterInterval>> site;   // encloses mesh.sites[i]
  std::vector<predicates::Sym2<FilterInterval>> metric;   // encloses mesh.metrics[i]
  std::vector<predicates::Point2<double>> approx;          // approximate(mesh.sites[i])
};

// The same for a tetrahedral mesh (issue 39).
struct EnclosedMesh3 {
  explicit EnclosedMesh3(const geometry::Mesh3<Rational>& m);

  // The exact orientation of vertices a, b, c, d (predicates/orientation3.hpp): the static
  // filter when the four are doubles (their enclosures are points), else intervals first.
  Sign orientation(int a, int b, int c, int d) const;
  // The orientation of tetrahedron t of the mesh, computed once by the constructor.
  Sign orientation(std::size_t t) const { return orientations[t]; }
  // Whether vertices u and v have exactly the same metric (a constant field: all do), from classes
  // of equal metrics formed once by the constructor (the enclosures hashed, the rationals compared).
  bool same_metric(int u, int v) const { return metric_class[static_cast<std::size_t>(u)] == metric_class[static_cast<std::size_t>(v)]; }
  // Whether the given vertices' coordinates and the metric of vertex `metric_vertex` are all doubles
  // (their enclosures points, their approximations exact): the static filters' inputs.
  template <std::size_t n>
  bool doubles(const std::array<int, n>& vertices, int metric_vertex) const {
    if (!exact_metric[static_cast<std::size_t>(metric_vertex)]) return false;
    for (const int u : vertices)
      if (!exact[static_cast<std::size_t>(u)]) return false;
    return true;
  }

  const geometry::Mesh3<Rational>& mesh;
  std::vector<char> exact;                                  // mesh.vertices[i]'s coordinates are doubles
  std::vector<char> exact_metric;                           // mesh.metrics[i]'s entries are doubles
  std::vector<int> metric_class;                            // equal for vertices with equal metrics
  std::vector<Sign> orientations;                           // of each tetrahedron
  std::vector<TetrahedronFace> faces;                       // every tetrahedron's four, equal ones adjacent
  std::vector<predicates::Point3<FilterInterval>> vertex;   // encloses mesh.vertices[i]
  std::vector<predicates::Sym3<FilterInterval>> metric;     // encloses mesh.metrics[i]
  std::vector<predicates::Point3<double>> approx;           // approximate(mesh.vertices[i])
};

// q rounded towards zero to a double (GMP's mpq_get_d): within one ulp, monotone, no allocation.
double approximate(const Rational& q);
// The tightest enclosure: the point [d, d] when q is the double d, else d widened by an ulp.
FilterInterval enclose(const Rational& q);
// A metric enclosure's midpoints, entry by entry: an approximate metric for measured values.
predicates::Sym3<double> midpoint(const predicates::Sym3<FilterInterval>& M);

}  // namespace anisocert::oracle
