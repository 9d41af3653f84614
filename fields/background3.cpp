#include "fields/background3.hpp"

#include "predicates/metric.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace anisocert::fields {
namespace {

using predicates::Point3;
using predicates::Sym3;

std::string vertex_text(std::size_t i) { return "background vertex " + std::to_string(i + 1) + " (counted from 1)"; }
std::string tetrahedron_text(std::size_t t) { return "background tetrahedron " + std::to_string(t + 1) + " (counted from 1 in the file's order)"; }

const geometry::Mesh3<Rational>& checked(const geometry::Mesh3<Rational>& mesh) {
  if (mesh.metrics.size() != mesh.vertices.size())
    throw BackgroundMeshError("the background mesh has " + std::to_string(mesh.vertices.size()) + " vertices but " +
                              std::to_string(mesh.metrics.size()) + " metrics");
  for (std::size_t i = 0; i < mesh.metrics.size(); ++i)
    if (!predicates::positive_definite(mesh.metrics[i])) throw BackgroundMeshError(vertex_text(i) + ": its metric is not positive definite");
  if (mesh.tetrahedra.empty()) throw BackgroundMeshError("the background mesh has no tetrahedra");
  const auto n = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& v = mesh.tetrahedra[t];
    for (int i : v)
      if (i < 0 || i >= n) throw BackgroundMeshError(tetrahedron_text(t) + " names a vertex beyond the " + std::to_string(n) + " there are");
    const auto at = [&](int k) { return mesh.vertices[static_cast<std::size_t>(v[static_cast<std::size_t>(k)])]; };
    if (predicates::orientation3(at(0), at(1), at(2), at(3)) == Sign::zero) throw BackgroundMeshError(tetrahedron_text(t) + " is flat");
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (const Rational* c : {&mesh.vertices[i].x, &mesh.vertices[i].y, &mesh.vertices[i].z})
      if (!std::isfinite(c->convert_to<double>())) throw BackgroundMeshError(vertex_text(i) + ": a coordinate beyond the doubles");
  return mesh;
}

Point3<FilterInterval> around(const Point3<Rational>& p) {
  return {FilterInterval::around(p.x), FilterInterval::around(p.y), FilterInterval::around(p.z)};
}

std::vector<Point3<FilterInterval>> intervals_of(const std::vector<Point3<Rational>>& vertices) {
  std::vector<Point3<FilterInterval>> x;
  for (const auto& p : vertices) x.push_back(around(p));
  return x;
}

std::vector<Sign> orientations_of(const std::vector<std::array<int, 4>>& tetrahedra, const std::vector<Point3<Rational>>& p) {
  std::vector<Sign> o;
  for (const auto& v : tetrahedra)
    o.push_back(predicates::orientation3(p[static_cast<std::size_t>(v[0])], p[static_cast<std::size_t>(v[1])], p[static_cast<std::size_t>(v[2])],
                                         p[static_cast<std::size_t>(v[3])]));
  return o;
}

// Each tetrahedron's range of one coordinate, the union of its vertices' intervals.
std::pair<double, double> range_of(const std::array<int, 4>& v, const std::vector<Point3<FilterInterval>>& x, FilterInterval Point3<FilterInterval>::*c) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k : v) lo = std::min(lo, (x[static_cast<std::size_t>(k)].*c).lo), hi = std::max(hi, (x[static_cast<std::size_t>(k)].*c).hi);
  return {lo, hi};
}

std::vector<DoubleBox> xy_boxes_of(const std::vector<std::array<int, 4>>& tetrahedra, const std::vector<Point3<FilterInterval>>& x) {
  std::vector<DoubleBox> boxes;
  for (const auto& v : tetrahedra) {
    const auto [x0, x1] = range_of(v, x, &Point3<FilterInterval>::x);
    const auto [y0, y1] = range_of(v, x, &Point3<FilterInterval>::y);
    boxes.push_back({x0, x1, y0, y1});
  }
  return boxes;
}

std::vector<std::pair<double, double>> z_ranges_of(const std::vector<std::array<int, 4>>& tetrahedra, const std::vector<Point3<FilterInterval>>& x) {
  std::vector<std::pair<double, double>> z;
  for (const auto& v : tetrahedra) z.push_back(range_of(v, x, &Point3<FilterInterval>::z));
  return z;
}

Rational volume6(const Point3<Rational>& a, const Point3<Rational>& b, const Point3<Rational>& c, const Point3<Rational>& d) {
  const Rational ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const Rational wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

}  // namespace

BackgroundMesh3::BackgroundMesh3(const geometry::Mesh3<Rational>& mesh)
    : vertices_(checked(mesh).vertices), metrics_(mesh.metrics), tetrahedra_(mesh.tetrahedra), vertex_intervals_(intervals_of(vertices_)),
      orientation_(orientations_of(tetrahedra_, vertices_)), boxes_(xy_boxes_of(tetrahedra_, vertex_intervals_)),
      z_ranges_(z_ranges_of(tetrahedra_, vertex_intervals_)), grid_(boxes_) {}

// p in the closed tetrahedron t: on its inner side of, or on, each face's plane (each orientation
// exact: the filtered predicate on the rationals).
bool BackgroundMesh3::holds(std::size_t t, const Point3<Rational>& p, const Point3<FilterInterval>& i) const {
  const DoubleBox& b = boxes_[t];
  if (i.x.hi < b.x0 || i.x.lo > b.x1 || i.y.hi < b.y0 || i.y.lo > b.y1 || i.z.hi < z_ranges_[t].first || i.z.lo > z_ranges_[t].second)
    return false;
  const auto& v = tetrahedra_[t];
  std::array<Point3<Rational>, 4> q;
  for (std::size_t k = 0; k < 4; ++k) q[k] = vertices_[static_cast<std::size_t>(v[k])];
  for (std::size_t k = 0; k < 4; ++k) {
    auto r = q;
    r[k] = p;  // p in place of vertex k: the same orientation or flat when p is on k's side of the opposite face
    const Sign s = predicates::orientation3(r[0], r[1], r[2], r[3]);
    if (s != Sign::zero && s != orientation_[t]) return false;
  }
  return true;
}

std::optional<Sym3<Rational>> BackgroundMesh3::metric_at(const Point3<Rational>& p) const {
  const Point3<FilterInterval> i = around(p);
  std::optional<std::size_t> found;
  grid_.visit({i.x.lo, i.x.hi, i.y.lo, i.y.hi}, [&](int id) {
    const auto t = static_cast<std::size_t>(id);
    if (found && t >= *found) return;
    if (holds(t, p, i)) found = t;
  });
  if (!found) return std::nullopt;
  const auto& v = tetrahedra_[*found];
  std::array<Point3<Rational>, 4> q;
  for (std::size_t k = 0; k < 4; ++k) q[k] = vertices_[static_cast<std::size_t>(v[k])];
  const Rational whole = volume6(q[0], q[1], q[2], q[3]);
  Sym3<Rational> M{0, 0, 0, 0, 0, 0};
  for (std::size_t k = 0; k < 4; ++k) {
    auto r = q;
    r[k] = p;
    const Rational lambda = volume6(r[0], r[1], r[2], r[3]) / whole;
    const auto& Mk = metrics_[static_cast<std::size_t>(v[k])];
    M.m11 += lambda * Mk.m11, M.m12 += lambda * Mk.m12, M.m13 += lambda * Mk.m13;
    M.m22 += lambda * Mk.m22, M.m23 += lambda * Mk.m23, M.m33 += lambda * Mk.m33;
  }
  return M;
}

}  // namespace anisocert::fields
