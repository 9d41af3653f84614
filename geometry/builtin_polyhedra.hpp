#pragma once
// The built-in 3D domains of `anisocert refine` (issue 40), the UGAWG benchmark's two geometries
// (github.com/UGAWG/adapt-benchmarks): `cube`, the unit cube [0, 1]³, and `cube-cylinder`, the unit
// cube with the cylinder x² + y² < 0.5² about the z axis removed (its README: "a unit cube with a
// cylinder of radius 0.5 centered about the z-axis Boolean subtracted from the cube"), the curved
// face approximated by `segments` planar strips. Every coordinate is a multiple of 2⁻²⁰ (the arc's
// points rounded to that grid, a distance below 10⁻⁶ from the circle), so that midpoints of
// midpoints stay exact doubles for about thirty halvings.
#include "geometry/polyhedron.hpp"

#include <array>
#include <string>
#include <vector>

namespace anisocert::geometry {

Polyhedron cube_polyhedron();
// The prism of height h over the counter-clockwise polygon p in z = 0, its end facets fanned from
// p[0] (so p must be star-shaped from p[0]), every facet outward (the tests' and fuzz harnesses'
// small polyhedra: boxes, a triangular prism, an L-shaped prism with a reflex ridge).
Polyhedron prism_polyhedron(const std::vector<std::array<Rational, 2>>& p, const Rational& h);
Polyhedron cube_cylinder_polyhedron(int segments = 16);

// The built-in's name → its polyhedron; nullptr for another name.
const Polyhedron* builtin_polyhedron(const std::string& name);
std::vector<std::string> builtin_polyhedron_names();

}  // namespace anisocert::geometry
