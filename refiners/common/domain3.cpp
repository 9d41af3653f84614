#include "refiners/common/domain3.hpp"

#include "numbers/shortest_decimal.hpp"
#include "refiners/common/exact_split.hpp"
#include "predicates/orientation.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace anisocert::refiners::common {

using anisocert::Sign;

std::string point_text(const Point3<double>& p) {
  return "(" + shortest_decimal(p.x) + ", " + shortest_decimal(p.y) + ", " + shortest_decimal(p.z) + ")";
}

namespace {

double exact_double(const Rational& q, std::size_t v, char axis) {
  const double d = q.convert_to<double>();
  if (!std::isfinite(d) || rational_from_double(d) != q)
    throw DomainError("vertex " + std::to_string(v) + " (from 0): its " + axis + " is not exactly a double, as 0.1 and 1/6 are not (the refiner " +
                      "puts boundary vertices exactly on the facets, in doubles: give coordinates such as multiples of 2⁻²⁰)");
  return d;
}

// Whether p, coplanar with the triangle abc, lies in it (closed), by the orientations of the
// projections onto the coordinate plane where abc is not flat (exactly: its projected orientation
// is not zero there, and projection keeps containment for coplanar points).
bool in_coplanar_triangle(const Point3<double>& p, const Point3<double>& a, const Point3<double>& b, const Point3<double>& c) {
  using P2 = predicates::Point2<double>;
  const std::array<P2 (*)(const Point3<double>&), 3> projections{
      [](const Point3<double>& q) { return P2{q.x, q.y}; }, [](const Point3<double>& q) { return P2{q.y, q.z}; },
      [](const Point3<double>& q) { return P2{q.z, q.x}; }};
  for (auto proj : projections) {
    const Sign s = predicates::orientation(proj(a), proj(b), proj(c));
    if (s == Sign::zero) continue;
    const Sign s1 = predicates::orientation(proj(a), proj(b), proj(p)), s2 = predicates::orientation(proj(b), proj(c), proj(p)),
               s3 = predicates::orientation(proj(c), proj(a), proj(p));
    return s1 != -s && s2 != -s && s3 != -s;
  }
  return false;  // abc collinear: excluded by polyhedron_defect
}

// Directions for the parity test, no two parallel: first +x, whose segment's box is thin, so that
// the facets' boxes dismiss nearly every facet; then eight in no coordinate plane.
constexpr std::array<std::array<double, 3>, 9> directions{{{1, 0, 0},
                                                           {0.5377, 0.3193, 0.7801},
                                                           {-0.2917, 0.8713, 0.3944},
                                                           {0.6611, -0.5419, 0.5189},
                                                           {-0.4427, -0.3359, -0.8311},
                                                           {0.1319, 0.9127, -0.3867},
                                                           {-0.7717, 0.2281, -0.5939},
                                                           {0.3187, -0.8231, -0.4699},
                                                           {0.8663, 0.1777, -0.4667}}};

// The least box holding the points (exact: comparisons of doubles).
Box3 box_of(const std::vector<Point3<double>>& points) {
  Box3 b{points[0].x, points[0].x, points[0].y, points[0].y, points[0].z, points[0].z};
  for (const auto& q : points) {
    b.x0 = std::min(b.x0, q.x), b.x1 = std::max(b.x1, q.x);
    b.y0 = std::min(b.y0, q.y), b.y1 = std::max(b.y1, q.y);
    b.z0 = std::min(b.z0, q.z), b.z1 = std::max(b.z1, q.z);
  }
  return b;
}

}  // namespace

Domain3::Domain3(const geometry::Polyhedron& p) {
  vertices_.reserve(p.vertices.size());
  for (std::size_t v = 0; v < p.vertices.size(); ++v)
    vertices_.push_back({exact_double(p.vertices[v].x, v, 'x'), exact_double(p.vertices[v].y, v, 'y'), exact_double(p.vertices[v].z, v, 'z')});
  if (const auto defect = geometry::polyhedron_defect(p)) throw DomainError(*defect);
  facets_ = p.facets;
  for (std::size_t f = 0; f < facets_.size(); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = facets_[f][e], b = facets_[f][(e + 1) % 3];
      if (exact_halvings(vertices_[a], vertices_[b]) < min_halvings)
        throw DomainError("facet " + std::to_string(f) + ": its edge from vertex " + std::to_string(a) + " to vertex " + std::to_string(b) +
                          " cannot be halved exactly " + std::to_string(min_halvings) +
                          " times in doubles (boundary vertices must lie exactly on the facets: round the coordinates to a coarser binary grid)");
    }
  box_ = box_of(vertices_);
  for (const auto& t : facets_) facet_boxes_.push_back(box_of({vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]}));
  const std::size_t n = facets_.size();
  coplanar_.assign(n * n, false);
  for (std::size_t f = 0; f < n; ++f)
    for (std::size_t g = 0; g < n; ++g) {
      const auto& a = facets_[f];
      bool all = true;
      for (int k : facets_[g])
        all = all && predicates::orientation3(vertices_[a[0]], vertices_[a[1]], vertices_[a[2]], vertices_[k]) == Sign::zero;
      coplanar_[f * n + g] = all;
    }
  for (std::size_t f = 0; f < n; ++f) {
    std::size_t g = 0;
    while (!coplanar_[f * n + g]) ++g;
    plane_.push_back(static_cast<int>(g));
  }
  for (const auto& t : facets_)
    for (const auto& q : vertices_)
      convex_ = convex_ && predicates::orientation3(vertices_[t[0]], vertices_[t[1]], vertices_[t[2]], q) != Sign::positive;
}

bool Domain3::on_facet(const Point3<double>& p, int f) const {
  const auto& t = facets_[f];
  const auto &a = vertices_[t[0]], &b = vertices_[t[1]], &c = vertices_[t[2]];
  return predicates::orientation3(a, b, c, p) == Sign::zero && in_coplanar_triangle(p, a, b, c);
}

Side Domain3::side(const Point3<double>& p) const {
  if (p.x < box_.x0 || p.x > box_.x1 || p.y < box_.y0 || p.y > box_.y1 || p.z < box_.z0 || p.z > box_.z1) return Side::outside;
  for (int f = 0; f < static_cast<int>(facets_.size()); ++f)
    if (facet_boxes_[f].contains(p) && on_facet(p, f)) return Side::boundary;
  // A far point beyond the box; the segment p → far crosses the surface an odd number of times
  // iff p is inside (p is on no facet).
  const double reach = 2 * ((box_.x1 - box_.x0) + (box_.y1 - box_.y0) + (box_.z1 - box_.z0)) + 1;
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;  // the pseudo-random directions after the fixed ones
  const auto next = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1p-53 * 2 - 1;  // in [−1, 1)
  };
  // A closed segment and a closed triangle in disjoint boxes do not meet: no crossing to count.
  for (std::size_t attempt = 0; attempt < directions.size() + 1000; ++attempt) {
    std::array<double, 3> d = attempt < directions.size() ? directions[attempt] : std::array<double, 3>{next(), next(), next()};
    if (attempt >= directions.size()) {  // normalised so that the far point is beyond the box
      const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(n > 0.1)) continue;
      d = {d[0] / n, d[1] / n, d[2] / n};
    }
    const Point3<double> far{p.x + reach * d[0], p.y + reach * d[1], p.z + reach * d[2]};
    const Box3 segment = box_of({p, far});
    bool degenerate = false, odd = false;
    for (std::size_t f = 0; f < facets_.size(); ++f) {
      if (!segment.meets(facet_boxes_[f])) continue;
      const auto& t = facets_[f];
      const auto &a = vertices_[t[0]], &b = vertices_[t[1]], &c = vertices_[t[2]];
      const Sign sp = predicates::orientation3(a, b, c, p), sf = predicates::orientation3(a, b, c, far);
      if (sf == Sign::zero) {
        if (in_coplanar_triangle(far, a, b, c) || sp == Sign::zero) degenerate = true;
        if (degenerate) break;
        continue;
      }
      if (sp == Sign::zero) {  // p in the plane, off the facet: the segment touches the plane only at p
        continue;
      }
      if (sp == sf) continue;
      const Sign s1 = predicates::orientation3(p, far, a, b), s2 = predicates::orientation3(p, far, b, c),
                 s3 = predicates::orientation3(p, far, c, a);
      if (s1 == Sign::zero || s2 == Sign::zero || s3 == Sign::zero) {
        degenerate = true;
        break;
      }
      if (s1 == s2 && s2 == s3) odd = !odd;
    }
    if (!degenerate) return odd ? Side::inside : Side::outside;
  }
  throw std::logic_error("Domain3::side: every direction from " + point_text(p) + " met a facet's edge or plane");
}

}  // namespace anisocert::refiners::common
