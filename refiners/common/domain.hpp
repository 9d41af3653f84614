#pragma once
// The domain Ω as every refiner sees it, checked once, here: a simple counter-clockwise polygon
// (geometry::simplicity_defect) whose corners are doubles (the refiners work in floating point)
// and whose edges can each be split exactly min_halvings times (exact_split.hpp: boundary
// vertices must lie exactly on ∂Ω: split_halvings). With it, the rest of a PSLG X (LS §9's input):
// points inside Ω, and interior segments between its vertices (the corners, then the points), each
// inside Ω but for its ends, meeting ∂Ω, other segments and vertices at its ends only, and
// halvable like an edge. X's segments are Ω's edges (0 … n − 1, edge k from corner k to corner k + 1) and then the
// interior ones. And the exact questions a refiner asks of it.
#include "geometry/polygon.hpp"
#include "numbers/shortest_decimal.hpp"
#include "refiners/common/errors.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace anisocert::refiners::common {

using geometry::Polygon;
using predicates::Point2;

// A closed axis-parallel box; empty when x0 > x1.
struct Box {
  double x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  bool contains(const Point2<double>& p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

// "(x, y)" with the shortest decimals that read back as the doubles (for messages).
std::string point_text(const Point2<double>& p);
// "a, b, c": three sites by their indices (for messages).
std::string trio_text(const std::array<int, 3>& t);
// "[m11, m12, m22]" likewise.
std::string metric_text(const predicates::Sym2<double>& M);

class Domain {
 public:
  // Throws DomainError naming the corner, point, edge or segment and what is wrong.
  explicit Domain(const Polygon<double>& corners, const std::vector<Point2<double>>& points = {},
                  const std::vector<std::pair<int, int>>& interior_segments = {});
  // The same from exact coordinates, each of which must be a double.
  static Domain from_exact(const Polygon<Rational>& corners, const std::vector<Point2<Rational>>& points = {},
                           const std::vector<std::pair<int, int>>& interior_segments = {});

  const Polygon<double>& corners() const { return corners_; }
  std::size_t size() const { return corners_.size(); }
  // X's vertices: the corners, then the points.
  const std::vector<Point2<double>>& vertices() const { return vertices_; }
  const std::vector<std::pair<int, int>>& interior_segments() const { return interior_; }
  bool has_interior() const { return vertices_.size() > corners_.size() || !interior_.empty(); }
  // X's segments: edges, then interior segments; the vertices segment e runs between.
  std::size_t segment_count() const { return corners_.size() + interior_.size(); }
  std::pair<int, int> segment_ends(std::size_t e) const;
  bool convex() const { return convex_; }
  Box bounding_box() const;
  // p in the closed polygon, exactly.
  bool contains(const Point2<double>& p) const { return geometry::in_closed_polygon(p, corners_); }
  // p (rational, e.g. a centroid of doubles) in the closed polygon, exactly.
  bool contains(const Point2<Rational>& p) const { return geometry::in_closed_polygon(p, exact_); }
  // The closed box b, a filter for a point known only to lie in it: true when all of b lies in
  // the closed polygon, false when none of it does, nothing when b may meet the boundary (or is
  // not finite). Exact: b meets no edge (decided by orientations of its corners), so its corners
  // share one answer.
  std::optional<bool> contains(const Box& b) const;
  // The segment ab crosses no edge of Ω properly (always true in a convex Ω, for a, b in Ω).
  bool visible(const Point2<double>& a, const Point2<double>& b) const { return convex_ || crosses_no_edge(a, b); }
  // "corner k (x, y)" or "point k (x, y)" for X's vertex k, with the shortest decimals that read
  // back as its doubles.
  std::string corner_text(std::size_t k) const;

 private:
  bool crosses_no_edge(const Point2<double>& a, const Point2<double>& b) const;
  // Throws DomainError naming the first edge that cannot be split min_halvings times (split_halvings).
  void check_halvings() const;
  void check_interior();

  Polygon<double> corners_;
  std::vector<Point2<double>> vertices_;
  std::vector<std::pair<int, int>> interior_;
  Polygon<Rational> exact_;
  bool convex_;
};

}  // namespace anisocert::refiners::common
