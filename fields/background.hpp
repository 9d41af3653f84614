#pragma once
// A metric field given by a background mesh with a metric at each vertex, the way MMG, BAMG and
// Gmsh users give one. Definition: P1 interpolation of the metric's components (m11, m12, m22)
// over the background triangle abc that holds p,
//   M(p) = λ_a M_a + λ_b M_b + λ_c M_c,   λ_a = [p b c] / [a b c], λ_b = [a p c] / [a b c], λ_c = [a b p] / [a b c],
// the barycentric coordinates of p in abc ([u v w] the orientation determinant of
// predicates/orientation.hpp). It is exact for rational data (every λ is rational when p and the
// vertices are) and positive definite: in the closed triangle λ ≥ 0 and Σ λ = 1, and a convex
// combination of positive definite matrices is positive definite.
// What it is not: MMG's default log-Euclidean interpolation (exp Σ λ_i log M_i, not rational), nor
// a metric intersection. On an edge or a vertex shared by several triangles every one of them
// gives the same value (P1 is continuous on a conforming mesh), so the choice of triangle never
// changes the answer; on a mesh that is not conforming (overlaps, hanging vertices) the triangle
// of lowest index is taken, so the value is still the mesh's alone. A point in no triangle has
// no value: no extrapolation.
#include "fields/box_grid.hpp"
#include "fields/metric_field.hpp"
#include "fields/p1_enclosure.hpp"
#include "geometry/mesh.hpp"

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace anisocert::fields {

using geometry::Point2;
using geometry::Sym2;

// A background mesh that defines no field: what() names the site or the triangle and what is
// wrong with it.
struct BackgroundMeshError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class BackgroundMesh {
 public:
  // Checks, exactly: a metric at every site, each positive definite; at least one triangle, each
  // naming existing sites and turning counter-clockwise (not flat); every coordinate within the
  // range of doubles (the location grid is in doubles). Throws BackgroundMeshError.
  explicit BackgroundMesh(const geometry::Mesh<Rational>& mesh);

  // M(p), exactly; nothing when no triangle holds p.
  std::optional<Sym2<Rational>> metric_at(const Point2<Rational>& p) const;
  // M(p) interpolated in triangle t; nothing when t does not hold p (closed triangle).
  std::optional<Sym2<Rational>> metric_in(int t, const Point2<Rational>& p) const;

  // M(p) for the refiners: p located exactly (each coordinate the rational it denotes), the value
  // within 2⁻⁴⁹ relative (about eight units in the last place) of the exact one: m11 and m22 of
  // themselves, m12 of √(m11 m22). From intervals when they are that tight (p1_enclosure.hpp),
  // else the exact value rounded to nearest; at a site, its own metric rounded to nearest. Nothing
  // when no triangle holds p or p is not finite.
  std::optional<Sym2<double>> metric_at(const Point2<double>& p) const;

  std::size_t triangle_count() const { return triangles_.size(); }

 private:
  struct Query;  // a point, exactly and as intervals
  bool holds(std::size_t t, const Query& q) const;
  // The triangle of lowest index holding q.
  std::optional<std::size_t> locate(const Query& q) const;

  std::vector<Point2<Rational>> sites_;
  std::vector<Sym2<Rational>> metrics_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Point2<FilterInterval>> site_intervals_;  // the sites' coordinates and metrics, each
  std::vector<Sym2<FilterInterval>> metric_intervals_;  // within one ulp of its nearest double
  std::vector<P1Gradient> gradients_;                   // each triangle's (p1_enclosure.hpp)
  std::vector<DoubleBox> boxes_;                        // each triangle's, from its sites' intervals
  BoxGrid grid_;
};

// The field for the refiners, named `name`: at(x, y) is mesh->metric_at({x, y}), and a point that
// no triangle holds throws FieldError naming the field and the point.
MetricField background_field(std::shared_ptr<const BackgroundMesh> mesh, const std::string& name);

}  // namespace anisocert::fields
