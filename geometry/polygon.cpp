#include "geometry/polygon.hpp"

#include "numbers/excerpt.hpp"
#include "numbers/filter_interval.hpp"

namespace anisocert::geometry {
namespace {

using Point = Point2<Rational>;

// The crossing point of two properly crossing segments: p1 + t (p2 − p1) with
// t = P(q1, q2, p1) / (P(q1, q2, p1) − P(q1, q2, p2)), P the orientation polynomial; the
// denominator is non-zero since the two values have opposite signs.
Point crossing_point(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const auto P = [](const Point& a, const Point& b, const Point& c) {
    return predicates::OrientationKernel::eval<Rational>({a.x, a.y, b.x, b.y, c.x, c.y});
  };
  const Rational s = P(q1, q2, p1), t = s / (s - P(q1, q2, p2));
  return {p1.x + t * (p2.x - p1.x), p1.y + t * (p2.y - p1.y)};
}

// Where two touching segments meet: the first endpoint of one that lies on the other.
Point touching_point(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  if (on_segment(q1, p1, p2)) return q1;
  if (on_segment(q2, p1, p2)) return q2;
  if (on_segment(p1, q1, q2)) return p1;
  return p2;
}

}  // namespace

std::string point_excerpt(const Point& p) { return "(" + exact_excerpt(p.x) + ", " + exact_excerpt(p.y) + ")"; }

std::string describe(const PolygonDefect& d, const Polygon<Rational>& v, const std::string& name) {
  const std::size_t m = v.size();
  const auto corner = [&](std::size_t k) { return name + "[" + std::to_string(k) + "]"; };
  const auto edge = [&](std::size_t k) {
    return "edge " + std::to_string(k) + " (" + corner(k) + " to " + corner((k + 1) % m) + ")";
  };
  switch (d.kind) {
    case PolygonDefect::Kind::zero_length_edge:
      return corner(d.i) + " and " + corner((d.i + 1) % m) + " are the same point " + point_excerpt(v[d.i]) + " (edge " +
             std::to_string(d.i) + " has length zero)";
    case PolygonDefect::Kind::folds_back:
      return "the boundary folds back at " + corner(d.i) + " " + point_excerpt(v[d.i]) + ": " + edge((d.i + m - 1) % m) + " and " +
             edge(d.i) + " overlap";
    case PolygonDefect::Kind::edges_meet:
      return edge(d.i) + " and " + edge(d.j) + (d.crossing ? " cross" : " touch") + " at " + point_excerpt(d.at) +
             "; the domain must be a simple polygon";
    case PolygonDefect::Kind::clockwise:
      return "the vertices are clockwise; list the vertices counter-clockwise";
  }
  return "";
}

SplitPolygon split_at_points(const Polygon<Rational>& polygon, const std::vector<Point>& points) {
  // Candidates by x first: the points sorted by a double box of x, so that an edge looks only at
  // those whose box meets its own x-range (a few per edge on a mesh's boundary); then exactly.
  const auto box = [](const Rational& r) { return FilterInterval::around(r); };
  std::vector<std::pair<double, int>> by_x;
  by_x.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) by_x.emplace_back(box(points[i].x).lo, static_cast<int>(i));
  std::sort(by_x.begin(), by_x.end());
  const std::size_t m = polygon.size();
  SplitPolygon out;
  for (std::size_t k = 0; k < m; ++k) {
    const Point& a = polygon[k];
    const Point& b = polygon[(k + 1) % m];
    out.corners.push_back(a);
    out.point.push_back(-1);
    const FilterInterval ax = box(a.x), bx = box(b.x);
    const double lo = std::min(ax.lo, bx.lo), hi = std::max(ax.hi, bx.hi);
    // A box's lower end is within two ulps below the exact value: start three steps below lo.
    const double start = FilterInterval::next_down(FilterInterval::next_down(FilterInterval::next_down(lo)));
    auto it = std::lower_bound(by_x.begin(), by_x.end(), std::pair{start, -1});
    std::vector<std::pair<Rational, int>> inside;  // (position along the edge, point)
    for (; it != by_x.end() && it->first <= hi; ++it) {
      const Point& p = points[static_cast<std::size_t>(it->second)];
      if (p.x == a.x && p.y == a.y) out.point.back() = it->second;
      if (!on_segment(p, a, b) || (p.x == a.x && p.y == a.y) || (p.x == b.x && p.y == b.y)) continue;
      inside.emplace_back(a.x != b.x ? abs(p.x - a.x) : abs(p.y - a.y), it->second);
    }
    std::sort(inside.begin(), inside.end());
    for (std::size_t j = 0; j < inside.size(); ++j) {
      if (j > 0 && inside[j].first == inside[j - 1].first) continue;  // the same point twice
      out.corners.push_back(points[static_cast<std::size_t>(inside[j].second)]);
      out.point.push_back(inside[j].second);
    }
  }
  return out;
}

std::optional<PolygonDefect> simplicity_defect(const Polygon<Rational>& v) {
  using Kind = PolygonDefect::Kind;
  const std::size_t m = v.size();
  for (std::size_t k = 0; k < m; ++k)
    if (v[k].x == v[(k + 1) % m].x && v[k].y == v[(k + 1) % m].y) return PolygonDefect{Kind::zero_length_edge, k};
  for (std::size_t k = 0; k < m; ++k) {
    const Point &a = v[(k + m - 1) % m], &b = v[k], &c = v[(k + 1) % m];
    if (predicates::orientation(a, b, c) == Sign::zero && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0)
      return PolygonDefect{Kind::folds_back, k};
  }
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 2; j < m; ++j) {
      if (i == 0 && j == m - 1) continue;  // adjacent through corner 0
      const Point &p1 = v[i], &p2 = v[i + 1], &q1 = v[j], &q2 = v[(j + 1) % m];
      switch (segments_meet(p1, p2, q1, q2)) {
        case Meeting::none: break;
        case Meeting::crossing: return PolygonDefect{Kind::edges_meet, i, j, true, crossing_point(p1, p2, q1, q2)};
        case Meeting::touching: return PolygonDefect{Kind::edges_meet, i, j, false, touching_point(p1, p2, q1, q2)};
      }
    }
  Rational twice_area = 0;
  for (std::size_t k = 0; k < m; ++k) twice_area += v[k].x * v[(k + 1) % m].y - v[(k + 1) % m].x * v[k].y;
  if (twice_area < 0) return PolygonDefect{Kind::clockwise};
  return std::nullopt;
}

}  // namespace anisocert::geometry
