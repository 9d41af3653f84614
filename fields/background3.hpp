#pragma once
// The 3D twin of background.hpp (issue 39): a metric field given by a tetrahedral background mesh
// with a 3×3 metric at each vertex, P1 per component over the tetrahedron abcd that holds p,
//   M(p) = λ_a M_a + λ_b M_b + λ_c M_c + λ_d M_d,  λ_a = [p b c d] / [a b c d], …,
// the barycentric coordinates from orientation determinants (predicates/orientation3.hpp), exact
// for rational data and positive definite in the closed tetrahedron (a convex combination). On a
// face, edge or vertex shared by several tetrahedra every one gives the same value (P1 is
// continuous on a conforming mesh); otherwise the tetrahedron of lowest index is taken. A point in
// no tetrahedron has no value. Tetrahedra may be of either orientation, each its own.
#include "fields/background.hpp"
#include "geometry/mesh3.hpp"

#include <array>
#include <optional>
#include <vector>

namespace anisocert::fields {

class BackgroundMesh3 {
 public:
  // Checks, exactly: a metric at every vertex, each positive definite (Sylvester's minors); at
  // least one tetrahedron, each naming existing vertices and not flat; every coordinate within
  // the doubles. Throws BackgroundMeshError naming the vertex or tetrahedron (counted from 1).
  explicit BackgroundMesh3(const geometry::Mesh3<Rational>& mesh);

  // M(p), exactly; nothing when no tetrahedron holds p.
  std::optional<predicates::Sym3<Rational>> metric_at(const predicates::Point3<Rational>& p) const;

  std::size_t tetrahedron_count() const { return tetrahedra_.size(); }

 private:
  bool holds(std::size_t t, const predicates::Point3<Rational>& p, const predicates::Point3<FilterInterval>& i) const;

  std::vector<predicates::Point3<Rational>> vertices_;
  std::vector<predicates::Sym3<Rational>> metrics_;
  std::vector<std::array<int, 4>> tetrahedra_;
  std::vector<predicates::Point3<FilterInterval>> vertex_intervals_;
  std::vector<Sign> orientation_;   // each tetrahedron's
  std::vector<DoubleBox> boxes_;    // each tetrahedron's (x, y) box; z in z_ranges_
  std::vector<std::pair<double, double>> z_ranges_;
  BoxGrid grid_;                    // over the (x, y) boxes: candidates, decided exactly
};

}  // namespace anisocert::fields
