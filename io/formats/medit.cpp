#include "io/formats/medit.hpp"

#include <sstream>

namespace anisocert::io {
namespace {

std::string round_trip(double x) {
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
}

}  // namespace

std::string medit_mesh(const geometry::Mesh<double>& m) {
  std::ostringstream o;
  o << "MeshVersionFormatted 2\nDimension 2\nVertices\n" << m.sites.size() << "\n";
  for (const auto& p : m.sites) o << round_trip(p.x) << " " << round_trip(p.y) << " 0\n";
  o << "Edges\n" << m.segments.size() << "\n";
  for (const auto& [a, b] : m.segments) o << a + 1 << " " << b + 1 << " 1\n";
  o << "Triangles\n" << m.triangles.size() << "\n";
  for (const auto& t : m.triangles) o << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << " 0\n";
  o << "End\n";
  return o.str();
}

std::string medit_sol(const geometry::Mesh<double>& m) {
  std::ostringstream o;
  o << "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n" << m.metrics.size() << "\n1 3\n";
  for (const auto& M : m.metrics) o << round_trip(M.m11) << " " << round_trip(M.m12) << " " << round_trip(M.m22) << "\n";
  o << "End\n";
  return o.str();
}

}  // namespace anisocert::io
