#include "refiners/common/domain.hpp"

#include "refiners/common/exact_split.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace anisocert::refiners::common {

std::string point_text(const Point2<double>& p) { return "(" + shortest_decimal(p.x) + ", " + shortest_decimal(p.y) + ")"; }
std::string trio_text(const std::array<int, 3>& t) { return std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]); }
std::string metric_text(const predicates::Sym2<double>& M) {
  return "[" + shortest_decimal(M.m11) + ", " + shortest_decimal(M.m12) + ", " + shortest_decimal(M.m22) + "]";
}

Domain::Domain(const Polygon<double>& corners, const std::vector<Point2<double>>& points,
               const std::vector<std::pair<int, int>>& interior_segments)
    : corners_(corners), interior_(interior_segments) {
  for (const auto& q : corners_) exact_.push_back({Rational(q.x), Rational(q.y)});
  if (corners_.size() < 3) throw DomainError("the domain needs at least 3 corners");
  if (const auto defect = geometry::simplicity_defect(exact_)) throw DomainError(geometry::describe(*defect, exact_, "domain"));
  check_halvings();
  convex_ = geometry::is_convex(corners_);
  vertices_ = corners_;
  vertices_.insert(vertices_.end(), points.begin(), points.end());
  check_interior();
}

Domain Domain::from_exact(const Polygon<Rational>& corners, const std::vector<Point2<Rational>>& points,
                          const std::vector<std::pair<int, int>>& interior_segments) {
  const auto doubles = [](const std::vector<Point2<Rational>>& in, const char* what) {
    Polygon<double> d;
    for (std::size_t k = 0; k < in.size(); ++k) {
      const Point2<Rational>& q = in[k];
      const double x = q.x.convert_to<double>(), y = q.y.convert_to<double>();
      if (!std::isfinite(x) || !std::isfinite(y) || Rational(x) != q.x || Rational(y) != q.y)
        throw DomainError(std::string(what) + " " + std::to_string(k) + " (" + exact_excerpt(q.x) + ", " + exact_excerpt(q.y) +
                          ") is not a double; the refiner works in floating point");
      d.push_back({x, y});
    }
    return d;
  };
  return Domain(doubles(corners, "domain vertex"), doubles(points, "point"), interior_segments);
}

void Domain::check_halvings() const {
  for (std::size_t i = 0; i < corners_.size(); ++i) {
    const Point2<double>&a = corners_[i], &b = corners_[(i + 1) % corners_.size()];
    const int k = split_halvings(a, b);
    if (k < min_halvings)
      throw DomainError("domain edge " + std::to_string(i) + " from " + point_text(a) + " to " + point_text(b) +
                        " can be halved exactly in doubles only " + std::to_string(k) + " times (" +
                        std::to_string(min_halvings) +
                        " needed: split points must lie exactly on the boundary); give the domain coordinates with fewer "
                        "binary digits, e.g. 0.375 or 13/32 rather than 0.4");
  }
}

std::pair<int, int> Domain::segment_ends(std::size_t e) const {
  const std::size_t n = corners_.size();
  if (e < n) return {static_cast<int>(e), static_cast<int>((e + 1) % n)};
  return interior_[e - n];
}

Box Domain::bounding_box() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box b{inf, -inf, inf, -inf};
  for (const auto& q : corners_) b.x0 = std::min(b.x0, q.x), b.y0 = std::min(b.y0, q.y), b.x1 = std::max(b.x1, q.x), b.y1 = std::max(b.y1, q.y);
  return b;
}

std::optional<bool> Domain::contains(const Box& b) const {
  if (!(std::isfinite(b.x0) && std::isfinite(b.x1) && std::isfinite(b.y0) && std::isfinite(b.y1)) || b.x0 > b.x1 || b.y0 > b.y1)
    return std::nullopt;
  const std::array<Point2<double>, 4> corner{Point2<double>{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}};
  const std::size_t m = corners_.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Point2<double>&p = corners_[k], &q = corners_[(k + 1) % m];
    if (std::max(p.x, q.x) < b.x0 || std::min(p.x, q.x) > b.x1 || std::max(p.y, q.y) < b.y0 || std::min(p.y, q.y) > b.y1) continue;
    const Sign side = predicates::orientation(p, q, corner[0]);
    if (side == Sign::zero) return std::nullopt;
    for (std::size_t i = 1; i < 4; ++i)
      if (predicates::orientation(p, q, corner[i]) != side) return std::nullopt;
  }
  return contains(corner[0]);
}

bool Domain::crosses_no_edge(const Point2<double>& a, const Point2<double>& b) const {
  for (std::size_t i = 0; i < corners_.size(); ++i)
    if (geometry::segments_cross(a, b, corners_[i], corners_[(i + 1) % corners_.size()])) return false;
  return true;
}

std::string Domain::corner_text(std::size_t k) const {
  if (k < corners_.size()) return "corner " + std::to_string(k) + " " + point_text(corners_[k]);
  return "point " + std::to_string(k - corners_.size()) + " " + point_text(vertices_[k]);
}

}  // namespace anisocert::refiners::common
