#include "geometry/mesh.hpp"

namespace anisocert::geometry {

Mesh<Rational> exact(const Mesh<double>& m) {
  Mesh<Rational> e;
  for (const auto& q : m.sites) e.sites.push_back({Rational(q.x), Rational(q.y)});
  for (const auto& M : m.metrics) e.metrics.push_back({Rational(M.m11), Rational(M.m12), Rational(M.m22)});
  for (const auto& q : m.domain) e.domain.push_back({Rational(q.x), Rational(q.y)});
  e.segments = m.segments, e.triangles = m.triangles;
  return e;
}

}  // namespace anisocert::geometry
