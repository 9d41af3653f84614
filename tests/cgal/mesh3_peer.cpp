// The CGAL Mesh_3 peer (issue 39, docs/validation.md § 3D peers): meshes the unit ball, an implicit
// domain, with a uniform size field (cell_size and facet_size h, CGAL's Mesh_criteria_3, radius–edge
// bound 2, facet angle 25°) and writes it as Medit with 17 significant digits (CGAL::IO::
// output_to_medit), so that `anisocert certify` reads the doubles CGAL computed.
//   cgal_mesh3_peer OUT.mesh H
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

K::FT ball(const K::Point_3& p) { return CGAL::squared_distance(p, K::Point_3(CGAL::ORIGIN)) - 1; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: cgal_mesh3_peer OUT.mesh H\n";
    return 2;
  }
  const double h = std::strtod(argv[2], nullptr);
  if (!(h > 0)) {
    std::cerr << "cgal_mesh3_peer: H must be positive\n";
    return 2;
  }
  CGAL::get_default_random() = CGAL::Random(39);  // the same mesh on every run
  namespace params = CGAL::parameters;
  const Domain domain = Domain::create_implicit_mesh_domain(ball, K::Sphere_3(CGAL::ORIGIN, K::FT(4)), params::relative_error_bound = 1e-6);
  const Criteria criteria(params::facet_angle = 25, params::facet_size = h, params::facet_distance = h / 10, params::cell_radius_edge_ratio = 2,
                          params::cell_size = h);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  std::ofstream out(argv[1]);
  out.precision(17);
  CGAL::IO::output_to_medit(out, c3t3);
  std::cout << "cgal_mesh3_peer: " << c3t3.triangulation().number_of_vertices() << " vertices, " << c3t3.number_of_cells_in_complex()
            << " tetrahedra in " << argv[1] << "\n";
  return out ? 0 : 1;
}
