#pragma once
// A 3D domain for `anisocert refine --domain FILE` (issue 40): a closed triangulated surface from
//  - Geomview OFF (.off): "OFF", the counts "V F E", V lines "x y z", F lines "3 i j k" (vertices
//    from 0; only triangles), '#' comments;
//  - a Medit .mesh/.meshb (Dimension 3, Vertices and Triangles) or a Gmsh .msh (its triangles):
//    a surface; a tetrahedral mesh gives its declared boundary triangles.
// Every number is read as the rational its text denotes; vertices no triangle uses are dropped
// (Gmsh writes the geometry's points), the rest renumbered in order. Whether the surface bounds a
// solid is geometry::polyhedron_defect's to say (the refiner asks).
#include "geometry/polyhedron.hpp"

#include <string>

namespace anisocert::io {

// Throws InputError naming the file, the place and what is wrong.
geometry::Polyhedron read_polyhedron_file(const std::string& path);

// Whether a --domain names a 3D domain: a built-in polyhedron (geometry/builtin_polyhedra.hpp) or
// a file this reader takes (.off, .mesh, .meshb, .msh); JSON domains are polygons.
bool names_polyhedron(const std::string& domain);

}  // namespace anisocert::io
