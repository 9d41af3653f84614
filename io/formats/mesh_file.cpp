#include "io/formats/mesh_file.hpp"

#include "numbers/excerpt.hpp"

#include <cmath>

namespace anisocert::io {

void set_constrained_segments(MeshFile& f) {
  f.mesh.segments.clear();
  for (const std::vector<int>* list : {&f.required_edges, &f.ridges})
    for (int e : *list) f.mesh.segments.push_back(f.mesh.edges.at(e));
}

void attach_metrics(MeshFile& f, std::vector<predicates::Sym2<Rational>> metrics, const std::string& source) {
  if (metrics.size() != f.mesh.sites.size())
    throw InputError(source + ": " + std::to_string(metrics.size()) + " metrics for a mesh of " +
                     std::to_string(f.mesh.sites.size()) + " vertices");
  f.mesh.metrics = std::move(metrics);
  f.metric_source = source;
}

void attach_metrics(MeshFile& f, std::vector<predicates::Sym3<Rational>> metrics, const std::string& source) {
  if (metrics.size() != f.mesh3.vertices.size())
    throw InputError(source + ": " + std::to_string(metrics.size()) + " metrics for a mesh of " +
                     std::to_string(f.mesh3.vertices.size()) + " vertices");
  f.mesh3.metrics = std::move(metrics);
  f.metric_source = source;
}

void require_triangle_mesh(const MeshFile& m, const std::string& format) {
  if (m.dimension == 3) throw InputError("a tetrahedral mesh cannot be written as " + format + " (Medit .mesh holds tetrahedra)");
}

predicates::Sym3<Rational> metric3_of_size(const Rational& h) {
  const Rational inv = 1 / (h * h);
  return {inv, 0, 0, inv, 0, inv};
}

predicates::Sym2<Rational> metric_of_size(const Rational& h) {
  const Rational inv = 1 / (h * h);
  return {inv, 0, inv};
}

std::string decimal_text(const Rational& q, const std::string& what) {
  std::string s = to_exact_string(q);
  if (s.find('/') != std::string::npos)
    throw InputError(what + " = " + excerpt(s) + " has no finite decimal expansion: the text format cannot hold it exactly");
  return s;
}

double exact_double(const Rational& q, const std::string& what) {
  const double d = q.convert_to<double>();
  if (!std::isfinite(d) || Rational(d) != q)
    throw InputError(what + " = " + exact_excerpt(q) + " is not a double: the binary format cannot hold it exactly");
  return d;
}

}  // namespace anisocert::io
