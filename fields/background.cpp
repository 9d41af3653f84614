#include "fields/background.hpp"

#include "numbers/shortest_decimal.hpp"
#include "predicates/metric.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::fields {
namespace {

// Triangles and sites counted from 1 in the order the file lists them (as Medit and FreeFem number
// them), and said so: a reader counting from 0 would be one off.
std::string site_text(std::size_t i) { return "background site " + std::to_string(i + 1) + " (counted from 1)"; }
std::string triangle_text(std::size_t t, const std::array<int, 3>& v) {
  return "background triangle " + std::to_string(t + 1) + " (sites " + std::to_string(v[0] + 1) + ", " + std::to_string(v[1] + 1) +
         ", " + std::to_string(v[2] + 1) + "; counted from 1 in the file's order)";
}

// The checks of the constructor (see background.hpp), in the order they are listed there.
const geometry::Mesh<Rational>& checked(const geometry::Mesh<Rational>& mesh) {
  if (mesh.metrics.size() != mesh.sites.size())
    throw BackgroundMeshError("the background mesh has " + std::to_string(mesh.sites.size()) + " sites but " +
                              std::to_string(mesh.metrics.size()) + " metrics");
  for (std::size_t i = 0; i < mesh.metrics.size(); ++i) try {
      predicates::Metric2{mesh.metrics[i]};
    } catch (const predicates::NotPositiveDefinite& e) {
      throw BackgroundMeshError(site_text(i) + ": " + e.what());
    }
  if (mesh.triangles.empty()) throw BackgroundMeshError("the background mesh has no triangles");
  const auto n = static_cast<int>(mesh.sites.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    for (int i : v)
      if (i < 0 || i >= n)
        throw BackgroundMeshError(triangle_text(t, v) + " names a site beyond the " + std::to_string(n) + " there are");
    const Sign o = predicates::orientation(mesh.sites[v[0]], mesh.sites[v[1]], mesh.sites[v[2]]);
    if (o == Sign::negative) throw BackgroundMeshError(triangle_text(t, v) + " is clockwise");
    if (o == Sign::zero)
      throw BackgroundMeshError(triangle_text(t, v) + " is flat: " + geometry::point_excerpt(mesh.sites[v[0]]) + ", " +
                                geometry::point_excerpt(mesh.sites[v[1]]) + " and " + geometry::point_excerpt(mesh.sites[v[2]]) +
                                " are collinear");
  }
  return mesh;
}

// Each triangle's box, the union of its vertices' intervals.
std::vector<DoubleBox> boxes_of(const std::vector<std::array<int, 3>>& triangles, const std::vector<Point2<FilterInterval>>& x) {
  std::vector<DoubleBox> boxes;
  for (const auto& [a, b, c] : triangles)
    boxes.push_back({std::min({x[a].x.lo, x[b].x.lo, x[c].x.lo}), std::max({x[a].x.hi, x[b].x.hi, x[c].x.hi}),
                     std::min({x[a].y.lo, x[b].y.lo, x[c].y.lo}), std::max({x[a].y.hi, x[b].y.hi, x[c].y.hi})});
  return boxes;
}

Point2<FilterInterval> around(const Point2<Rational>& p) { return {FilterInterval::around(p.x), FilterInterval::around(p.y)}; }

Sym2<FilterInterval> around(const Sym2<Rational>& M) {
  return {FilterInterval::around(M.m11), FilterInterval::around(M.m12), FilterInterval::around(M.m22)};
}

// The sites' intervals; every bound finite (the grid needs it).
std::vector<Point2<FilterInterval>> site_intervals(const std::vector<Point2<Rational>>& sites) {
  std::vector<Point2<FilterInterval>> x;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    x.push_back(around(sites[i]));
    if (!std::isfinite(x.back().x.lo) || !std::isfinite(x.back().x.hi) || !std::isfinite(x.back().y.lo) ||
        !std::isfinite(x.back().y.hi))
      throw BackgroundMeshError(site_text(i) + " " + geometry::point_excerpt(sites[i]) +
                                " lies beyond the range of doubles");
  }
  return x;
}

// [u v w], the orientation determinant (twice the signed area of uvw).
Rational area2(const Point2<Rational>& u, const Point2<Rational>& v, const Point2<Rational>& w) {
  return predicates::OrientationKernel::eval<Rational>({u.x, u.y, v.x, v.y, w.x, w.y});
}

// M(p) = ([p b c] M_a + [a p c] M_b + [a b p] M_c) / [a b c] in the triangle abc (background.hpp).
Sym2<Rational> interpolate(const std::array<int, 3>& v, const std::vector<Point2<Rational>>& x,
                           const std::vector<Sym2<Rational>>& M, const Point2<Rational>& p) {
  const int a = v[0], b = v[1], c = v[2];  // not a structured binding: the lambda below uses them
  const Rational wa = area2(p, x[b], x[c]), wb = area2(x[a], p, x[c]), wc = area2(x[a], x[b], p), w = wa + wb + wc;
  const auto mix = [&](Rational Sym2<Rational>::*m) { return (wa * (M[a].*m) + wb * (M[b].*m) + wc * (M[c].*m)) / w; };
  return {mix(&Sym2<Rational>::m11), mix(&Sym2<Rational>::m12), mix(&Sym2<Rational>::m22)};
}

}  // namespace

// A point exactly, and its intervals (a double's are the point itself).
struct BackgroundMesh::Query {
  Point2<Rational> exact;
  Point2<FilterInterval> interval;
};

BackgroundMesh::BackgroundMesh(const geometry::Mesh<Rational>& mesh)
    : sites_(checked(mesh).sites), metrics_(mesh.metrics), triangles_(mesh.triangles), site_intervals_(site_intervals(sites_)),
      boxes_(boxes_of(triangles_, site_intervals_)), grid_(boxes_) {
  for (const Sym2<Rational>& M : metrics_) metric_intervals_.push_back(around(M));
  const auto& x = site_intervals_;
  const auto& M = metric_intervals_;
  for (const auto& [a, b, c] : triangles_) gradients_.push_back(p1_gradient(x[a], x[b], x[c], M[a], M[b], M[c]));
}

// q in the closed counter-clockwise triangle abc: on the left of, or on, each edge's line. Each
// orientation in intervals first, exactly when they cannot tell (predicates/filtered_sign.hpp).
bool BackgroundMesh::holds(std::size_t t, const Query& q) const {
  const auto on_left = [&](int u, int v) {
    const Point2<FilterInterval>&iu = site_intervals_[u], &iv = site_intervals_[v];
    const Sign s = predicates::interval_then_exact<predicates::OrientationKernel>(
        {iu.x, iu.y, iv.x, iv.y, q.interval.x, q.interval.y}, [&] {
          return std::array<Rational, 6>{sites_[u].x, sites_[u].y, sites_[v].x, sites_[v].y, q.exact.x, q.exact.y};
        });
    return s != Sign::negative;
  };
  const auto& [a, b, c] = triangles_[t];
  return on_left(a, b) && on_left(b, c) && on_left(c, a);
}

std::optional<std::size_t> BackgroundMesh::locate(const Query& q) const {
  const DoubleBox box{q.interval.x.lo, q.interval.x.hi, q.interval.y.lo, q.interval.y.hi};
  std::optional<std::size_t> found;
  grid_.visit(box, [&](int id) {
    const auto t = static_cast<std::size_t>(id);
    const DoubleBox& b = boxes_[t];
    if ((found && t >= *found) || box.x1 < b.x0 || box.x0 > b.x1 || box.y1 < b.y0 || box.y0 > b.y1) return;
    if (holds(t, q)) found = t;
  });
  return found;
}

std::optional<Sym2<Rational>> BackgroundMesh::metric_at(const Point2<Rational>& p) const {
  if (const auto t = locate({p, around(p)})) return interpolate(triangles_[*t], sites_, metrics_, p);
  return std::nullopt;
}

std::optional<Sym2<Rational>> BackgroundMesh::metric_in(int t, const Point2<Rational>& p) const {
  const auto k = static_cast<std::size_t>(t);
  if (t < 0 || k >= triangles_.size() || !holds(k, {p, around(p)})) return std::nullopt;
  return interpolate(triangles_[k], sites_, metrics_, p);
}

std::optional<Sym2<double>> BackgroundMesh::metric_at(const Point2<double>& p) const {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::nullopt;
  const Query q{{Rational(p.x), Rational(p.y)}, {p.x, p.y}};
  const auto t = locate(q);
  if (!t) return std::nullopt;
  // At a site, M is the site's own metric, rounded to nearest (the intervals' midpoint can be ulps
  // off: 16 came back as 16 + 2⁻⁴⁸, and an edge of exactly √2 in M looked longer).
  for (const int v : triangles_[*t])
    if (const Point2<Rational>& site = sites_[static_cast<std::size_t>(v)]; q.exact.x == site.x && q.exact.y == site.y) {
      const Sym2<Rational>& M = metrics_[static_cast<std::size_t>(v)];
      return Sym2<double>{M.m11.convert_to<double>(), M.m12.convert_to<double>(), M.m22.convert_to<double>()};
    }
  const int a = triangles_[*t][0];
  if (const auto M = tight_midpoints(p1_value(site_intervals_[a], metric_intervals_[a], gradients_[*t], q.interval))) return M;
  const Sym2<Rational> M = interpolate(triangles_[*t], sites_, metrics_, q.exact);
  return Sym2<double>{M.m11.convert_to<double>(), M.m12.convert_to<double>(), M.m22.convert_to<double>()};
}

MetricField background_field(std::shared_ptr<const BackgroundMesh> mesh, const std::string& name) {
  return {name, {}, [mesh = std::move(mesh), name](double x, double y) {
            if (const auto M = mesh->metric_at(Point2<double>{x, y})) return *M;
            throw FieldError("the metric field " + name + " has no value at (" + shortest_decimal(x) + ", " +
                             shortest_decimal(y) + "): no background triangle holds it");
          }};
}

}  // namespace anisocert::fields
