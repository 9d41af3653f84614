#pragma once
// The domain Ω in 3D as the star refiner sees it (issue 40; LU §4 meshes a polyhedron), checked
// once, here: a closed, outward, non-self-intersecting triangulated surface
// (geometry::polyhedron_defect, exact) whose vertices are doubles (the refiners work in floating
// point). The 3D twin of domain.hpp, and the exact questions a refiner asks of it.
#include "geometry/polyhedron.hpp"
#include "refiners/common/errors.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace anisocert::refiners::common {

using predicates::Point3;
using predicates::Sym3;

// A closed axis-parallel box in space; empty when x0 > x1.
struct Box3 {
  double x0 = 0, x1 = -1, y0 = 0, y1 = -1, z0 = 0, z1 = -1;
  bool contains(const Point3<double>& p) const {
    return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1 && p.z >= z0 && p.z <= z1;
  }
  bool empty() const { return x0 > x1; }
  // Whether the two closed boxes share a point (exact: comparisons of doubles).
  bool meets(const Box3& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1 && z0 <= o.z1 && o.z0 <= z1; }
  // The least box holding both (either may be empty).
  Box3 hull(const Box3& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {std::min(x0, o.x0), std::max(x1, o.x1), std::min(y0, o.y0), std::max(y1, o.y1), std::min(z0, o.z0), std::max(z1, o.z1)};
  }
};

// "(x, y, z)" with the shortest decimals that read back as the doubles (for messages).
std::string point_text(const Point3<double>& p);

enum class Side { inside, boundary, outside };

class Domain3 {
 public:
  // Throws DomainError: a coordinate that is not a double (naming the vertex), or the polyhedron's
  // defect (naming the facet, edge or vertex).
  explicit Domain3(const geometry::Polyhedron& p);

  const std::vector<Point3<double>>& vertices() const { return vertices_; }
  const std::vector<std::array<int, 3>>& facets() const { return facets_; }
  const Box3& bounding_box() const { return box_; }
  // Where p is, exactly: the parity of the facets a segment from p to a far point crosses, every
  // decision an exact orientation; a segment through a facet's edge or vertex, or along its plane,
  // is replaced by another (the degenerate directions lie on finitely many planes through p: +x,
  // eight fixed directions, then up to 1,000 pseudo-random ones; throws std::logic_error should
  // all fail). Facets whose boxes miss the segment's are not tested.
  Side side(const Point3<double>& p) const;
  bool contains(const Point3<double>& p) const { return side(p) != Side::outside; }
  // Whether p lies on facet f (its closed triangle), exactly.
  bool on_facet(const Point3<double>& p, int f) const;
  // Whether every vertex lies on or behind every facet's plane (exactly): Ω is convex.
  bool convex() const { return convex_; }
  // Whether facets f and g lie in one plane, exactly.
  bool coplanar(int f, int g) const { return coplanar_[static_cast<std::size_t>(f) * facets_.size() + g]; }
  // The plane of facet f: the least facet coplanar with f.
  int plane_of(int f) const { return plane_[f]; }

 private:
  std::vector<Point3<double>> vertices_;
  std::vector<std::array<int, 3>> facets_;
  std::vector<bool> coplanar_;
  std::vector<int> plane_;
  Box3 box_;
  std::vector<Box3> facet_boxes_;
  bool convex_ = true;
};

}  // namespace anisocert::refiners::common
