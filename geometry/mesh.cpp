#include "geometry/mesh.hpp"

namespace anisocert::geometry {

Mesh<Rational> exact(const Mesh<double>& m) {
  Mesh<Rational> e;
  for (const auto& q : m.sites) e.sites.push_back({rational_from_double(q.x), rational_from_double(q.y)});
  for (const auto& M : m.metrics) e.metrics.push_back({rational_from_double(M.m11), rational_from_double(M.m12), rational_from_double(M.m22)});
  for (const auto& q : m.domain) e.domain.push_back({rational_from_double(q.x), rational_from_double(q.y)});
  e.segments = m.segments, e.edges = m.edges, e.triangles = m.triangles;
  return e;
}

}  // namespace anisocert::geometry
