#pragma once
// The Kuhn (Freudenthal) tetrahedral mesh of an n × n × n grid of unit cubes: each cube cut into
// the six tetrahedra 0, e_a, e_a + e_b, (1, 1, 1) around its main diagonal, one per order (a, b, c)
// of the axes, all positively oriented (Medit's convention); vertex (i, j, k) has index
// (i (n + 1) + j)(n + 1) + k. A mesh whose answers are known: valid, and for M = I each cube's eight
// corners are cospherical with no other vertex on the sphere. No metrics.
#include "geometry/mesh3.hpp"
#include "numbers/rational.hpp"

namespace anisocert::geometry {

Mesh3<Rational> kuhn_grid(int n);

}  // namespace anisocert::geometry
