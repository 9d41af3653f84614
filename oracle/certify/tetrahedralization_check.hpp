#pragma once
// Whether a tetrahedral mesh is valid (issue 39; LU §2–§4 mesh a 3D domain), decided exactly:
//  - orientation: every tetrahedron has the same non-zero orientation3 sign (orientation3.hpp:
//    positive is Medit's convention, det[b − a; c − a; d − a] > 0; all negative is accepted and
//    said), none flat; a mix is refused, the tetrahedra of the rarer sign named;
//  - faces: each face (a triangle of a tetrahedron) in exactly two tetrahedra that lie on opposite
//    sides of it (their outward orientations of the face are opposite), or in one (a boundary
//    face); a face in three or more, or in two on the same side, is named;
//  - every vertex is a vertex of some tetrahedron;
//  - the boundary is a closed 2-manifold: every edge of a boundary face is in exactly two boundary
//    faces (no pinched edge), and the boundary faces at a vertex form one cycle around it (no
//    pinched vertex);
//  - when the file declares triangles, every boundary face is one of them, and each of them is a
//    face of the tetrahedra, declared once (as a set of three vertices; either orientation), or
//    once in each orientation (CGAL's Medit writer lists a surface facet from both sides: counted,
//    not a failure): a boundary face, or an interior face between two subdomains (an interface, as
//    MMG and Gmsh write the surfaces between volumes: counted, not a failure).
// These are local conditions. Together they make the tetrahedra a consistently oriented
// 3-pseudomanifold whose boundary is a closed oriented surface, so each point off that surface is
// covered by as many tetrahedra as the surface winds around it; that the surface does not
// intersect itself, and so winds once around the domain, is not checked here (the check says so
// in `checks_run`).
// Witnesses name tetrahedra, faces and vertices numbered from 0 in the order of the file.
// Cost: one orientation per tetrahedron and the 4n faces in order, both made by EnclosedMesh3.
#include "oracle/certify/enclosed_mesh.hpp"

#include <string>
#include <vector>

namespace anisocert::oracle {

struct TetrahedralizationCheck {
  bool valid = false;
  // "positive" (Medit's), "negative", or empty when no tetrahedron has a non-zero orientation.
  std::string orientation;
  std::size_t boundary_faces = 0, interior_faces = 0;
  std::size_t declared_interfaces = 0;  // declared triangles that are interior faces
  std::size_t declared_both_sides = 0;  // faces declared a second time, in the other orientation
  std::vector<std::string> checks_run;
  std::vector<std::string> failures;  // the first `described`
  std::size_t failure_count = 0;      // all of them
  std::size_t described = 1000;
  std::vector<int> bad_tetrahedra;    // every tetrahedron named by a failure (sorted, once each)
  void fail(std::string text);
};

TetrahedralizationCheck check_tetrahedralization(const EnclosedMesh3& mesh, std::size_t described = 1000);

}  // namespace anisocert::oracle
