#pragma once
// Orientation of four points in space (LU §2: the tetrahedra of a star, positively oriented).
// P = det [ b − a ; c − a ; d − a ]: degree 3 in the coordinates. Positive when (a, b, c, d) is
// positively oriented, i.e. d lies on the side of the plane abc that (b − a) × (c − a) points
// to (the Medit convention for a tetrahedron's vertices); zero when the four are coplanar.

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct Orientation3Kernel {
  static constexpr const char* name = "orientation3";
  static constexpr std::size_t arity = 12;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  static constexpr std::array<const char*, arity> inputs{"a.x", "a.y", "a.z", "b.x", "b.y", "b.z",
                                                         "c.x", "c.y", "c.z", "d.x", "d.y", "d.z"};
  static constexpr std::array<int, arity> origin{0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2};  // differences from a
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const T bx = x[3] - x[0], by = x[4] - x[1], bz = x[5] - x[2];
    const T cx = x[6] - x[0], cy = x[7] - x[1], cz = x[8] - x[2];
    const T dx = x[9] - x[0], dy = x[10] - x[1], dz = x[11] - x[2];
    return bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
  }
};

template <class S>
Sign orientation3(const Point3<S>& a, const Point3<S>& b, const Point3<S>& c, const Point3<S>& d) {
  return filtered_sign<Orientation3Kernel>(std::array<S, 12>{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z});
}

}  // namespace anisocert::predicates
