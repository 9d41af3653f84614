#include "refiners/ls/delaunay_in_metric.hpp"

#include "predicates/incircle.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace anisocert::refiners::ls {

using anisocert::Sign;

DelaunayInMetric::DelaunayInMetric(const Sym2<double>& M, const common::Box& extent) : M_(M) {
  const double cx = (extent.x0 + extent.x1) / 2, cy = (extent.y0 + extent.y1) / 2;
  double size = std::max(extent.x1 - extent.x0, extent.y1 - extent.y0);
  if (!(size > 0)) size = std::max({std::abs(cx), std::abs(cy), 1.0});
  // A triangle dual to a vertex c in the box has its M-circumradius at most the box's M-diameter,
  // √λmax·√2·size, and a ghost lies at M-distance at least √λmin·(r − √2·size) from c. So
  // r > √2·size·(1 + √(λmax/λmin)) keeps every ghost outside those discs; trace/√det bounds
  // √(λmax/λmin) from above, and 1024 leaves room for rounding.
  const double stretch = (M.m11 + M.m22) / std::sqrt(M.m11 * M.m22 - M.m12 * M.m12);
  const double r = 1024 * size * (1 + stretch);
  ghosts_ = {Point2<double>{cx, cy + 2 * r}, Point2<double>{cx - 1.8 * r, cy - r}, Point2<double>{cx + 1.8 * r, cy - r}};
  triangles_.push_back({{-1, -2, -3}, {-1, -1, -1}, true});
  box_.emplace_back();
}

bool DelaunayInMetric::real(int t) const {
  const auto& v = triangles_[t].v;
  return v[0] >= 0 && v[1] >= 0 && v[2] >= 0;
}

// The visibility walk: from the last triangle created, across an edge that has p strictly on its
// other side, until none has (p in the closed triangle). It ends in a Delaunay triangulation (of
// the mapped points: orientation is invariant under F), whatever edge it tries first; the first
// edge tried rotates so that it does not favour one direction.
int DelaunayInMetric::locate(const Point2<double>& p) const {
  int t = recent_;
  for (std::size_t steps = 0, first = 0;; ++steps, first = (first + 1) % 3) {
    if (steps > 4 * triangles_.size() + 16) throw std::logic_error("DelaunayInMetric: the walk does not end");
    const Triangle& tri = triangles_[t];
    int next = -1;
    for (std::size_t k = 0; k < 3 && next < 0; ++k) {
      const std::size_t i = (first + k) % 3;
      if (predicates::orientation(point(tri.v[(i + 1) % 3]), point(tri.v[(i + 2) % 3]), p) == Sign::negative) next = tri.across[i];
    }
    if (next == -1) {
      for (std::size_t k = 0; k < 3; ++k)
        if (predicates::orientation(point(tri.v[(k + 1) % 3]), point(tri.v[(k + 2) % 3]), p) == Sign::negative)
          throw std::invalid_argument("DelaunayInMetric: a site outside the ghost triangle");
      return t;
    }
    t = next;
  }
}

int DelaunayInMetric::new_triangle(const std::array<int, 3>& v) {
  const Triangle tri{v, {-1, -1, -1}, true};
  if (!free_.empty()) {
    const int t = free_.back();
    free_.pop_back();
    triangles_[t] = tri;
    box_[static_cast<std::size_t>(t)].reset();
    return t;
  }
  triangles_.push_back(tri);
  box_.emplace_back();
  return static_cast<int>(triangles_.size()) - 1;
}

// Bowyer–Watson: the cavity is the set of triangles whose open M-circumdisc holds p (connected
// and star-shaped from p); it is replaced by the fan of p over its boundary. Cocircular
// neighbours (in-circle zero) stay: either diagonal of a cocircular quadrilateral is Del_M.
const std::vector<int>& DelaunayInMetric::insert(int id, const Point2<double>& p) {
  if (id != static_cast<int>(points_.size())) throw std::logic_error("DelaunayInMetric: sites are inserted in order");
  const int start = locate(p);
  for (int u : triangles_[start].v)
    if (point(u).x == p.x && point(u).y == p.y) throw std::invalid_argument("DelaunayInMetric: a site inserted twice");
  points_.push_back(p);

  // This insertion's marks: stamp_[t] is inside or outside, or older (unseen).
  stamp_.resize(triangles_.size(), 0);
  generation_ += 2;
  const unsigned inside = generation_, outside = generation_ + 1;
  cavity_.assign(1, start);
  stamp_[start] = inside;
  rim_.clear();
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const int t = cavity_[k];
    for (int i = 0; i < 3; ++i) {
      const int n = triangles_[t].across[i];
      if (n >= 0 && stamp_[n] != inside && stamp_[n] != outside) {
        const auto& w = triangles_[n].v;
        const bool in = predicates::incircle(point(w[0]), point(w[1]), point(w[2]), p, M_) == Sign::positive;
        stamp_[n] = in ? inside : outside;
        if (in) cavity_.push_back(n);
      }
      if (n < 0 || stamp_[n] == outside) rim_.emplace_back(t, i);
    }
  }

  struct Rim {
    int a, b, outside;
  };
  std::vector<Rim> rim;
  rim.reserve(rim_.size());
  for (const auto& [t, i] : rim_) rim.push_back({triangles_[t].v[(i + 1) % 3], triangles_[t].v[(i + 2) % 3], triangles_[t].across[i]});
  for (int t : cavity_) {
    triangles_[t].alive = false;
    free_.push_back(t);
  }
  created_.clear();
  for (const Rim& r : rim) {
    const int t = new_triangle({r.a, r.b, id});
    triangles_[t].across[2] = r.outside;
    if (r.outside >= 0) {
      Triangle& o = triangles_[r.outside];
      for (int j = 0; j < 3; ++j)
        if (o.v[(j + 1) % 3] == r.b && o.v[(j + 2) % 3] == r.a) o.across[j] = t;
    }
    created_.push_back(t);
  }
  // Across the edge (b, p) of (a, b, p) lies the new triangle that starts at b; across (p, a) the
  // one that ends at a.
  for (int t : created_) {
    Triangle& tri = triangles_[t];
    for (int u : created_) {
      if (triangles_[u].v[0] == tri.v[1]) tri.across[0] = u;
      if (triangles_[u].v[1] == tri.v[0]) tri.across[1] = u;
    }
  }
  recent_ = created_.front();
  return created_;
}

}  // namespace anisocert::refiners::ls
