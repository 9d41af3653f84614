#include "geometry/polyhedron.hpp"

#include "geometry/closed_surface.hpp"
#include "geometry/polygon.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace anisocert::geometry {
namespace {

using P3 = predicates::Point3<Rational>;
using P2 = predicates::Point2<Rational>;

Sign orient(const P3& a, const P3& b, const P3& c, const P3& d) { return predicates::orientation3(a, b, c, d); }

// The projection dropping one coordinate in which a, b, c (not collinear) stay a triangle.
struct Projection {
  int drop;
  P2 operator()(const P3& p) const { return drop == 0 ? P2{p.y, p.z} : drop == 1 ? P2{p.z, p.x} : P2{p.x, p.y}; }
};
Projection projection(const P3& a, const P3& b, const P3& c) {
  for (int drop = 2; drop >= 0; --drop) {
    const Projection f{drop};
    if (predicates::orientation(f(a), f(b), f(c)) != Sign::zero) return f;
  }
  return {2};  // collinear: refused before any pair is tested
}

bool collinear(const P3& a, const P3& b, const P3& c) {
  const Rational ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  return uy * vz == uz * vy && uz * vx == ux * vz && ux * vy == uy * vx;
}

// The closed segment pq meets the closed triangle abc (not collinear).
bool segment_meets_triangle(const P3& p, const P3& q, const P3& a, const P3& b, const P3& c) {
  const Sign op = orient(a, b, c, p), oq = orient(a, b, c, q);
  if (op == oq && op != Sign::zero) return false;
  if (op == Sign::zero && oq == Sign::zero) {  // in the triangle's plane
    const Projection f = projection(a, b, c);
    const Polygon<Rational> t = predicates::orientation(f(a), f(b), f(c)) == Sign::positive ? Polygon<Rational>{f(a), f(b), f(c)}
                                                                                             : Polygon<Rational>{f(a), f(c), f(b)};
    if (in_closed_polygon(f(p), t) || in_closed_polygon(f(q), t)) return true;
    for (std::size_t k = 0; k < 3; ++k)
      if (segments_meet(f(p), f(q), t[k], t[(k + 1) % 3]) != Meeting::none) return true;
    return false;
  }
  // pq reaches the plane at one point: inside the closed triangle when the line pq passes on one
  // side of each edge (or on it), the same side for all three.
  const Sign s1 = orient(p, q, a, b), s2 = orient(p, q, b, c), s3 = orient(p, q, c, a);
  const bool nonnegative = s1 != Sign::negative && s2 != Sign::negative && s3 != Sign::negative;
  const bool nonpositive = s1 != Sign::positive && s2 != Sign::positive && s3 != Sign::positive;
  return nonnegative || nonpositive;
}

std::string facet_name(std::size_t k) { return "facet " + std::to_string(k); }

}  // namespace

bool facets_meet(const std::vector<P3>& x, const std::array<int, 3>& t, const std::array<int, 3>& u) {
  const auto at = [&](int i) -> const P3& { return x[static_cast<std::size_t>(i)]; };
  std::array<int, 3> shared{};
  std::size_t n = 0;
  for (const int i : t)
    if (std::find(u.begin(), u.end(), i) != u.end()) shared[n++] = i;
  // The vertices of t (u) other than the shared ones, in t's (u's) order.
  const auto others = [&](const std::array<int, 3>& f) {
    std::vector<int> o;
    for (const int i : f)
      if (std::find(shared.begin(), shared.begin() + static_cast<long>(n), i) == shared.begin() + static_cast<long>(n)) o.push_back(i);
    return o;
  };
  const auto edge_meets = [&](int p, int q, const std::array<int, 3>& f) { return segment_meets_triangle(at(p), at(q), at(f[0]), at(f[1]), at(f[2])); };
  if (n == 0) {
    for (std::size_t k = 0; k < 3; ++k)
      if (edge_meets(t[k], t[(k + 1) % 3], u) || edge_meets(u[k], u[(k + 1) % 3], t)) return true;
    return false;
  }
  const std::vector<int> ot = others(t), ou = others(u);
  if (n == 1)  // t = (s, a, b), u = (s, c, d): beyond s they meet in a segment from s (or a region at s,
                // coplanar), which leaves one of them through its edge opposite s at a point of the other
    return edge_meets(ot[0], ot[1], u) || edge_meets(ou[0], ou[1], t);
  if (n == 2) {  // coplanar and on the same side of the shared edge: they overlap
    const P3 &s = at(shared[0]), &r = at(shared[1]), &a = at(ot[0]), &b = at(ou[0]);
    if (orient(s, r, a, b) != Sign::zero) return false;
    const Projection f = projection(s, r, a);
    return predicates::orientation(f(s), f(r), f(a)) == predicates::orientation(f(s), f(r), f(b));
  }
  return true;  // the same three vertices twice (the surface check names it first)
}

std::optional<std::string> polyhedron_defect(const Polyhedron& p) {
  const auto& x = p.vertices;
  const long n = static_cast<long>(x.size());
  for (std::size_t k = 0; k < p.facets.size(); ++k) {
    const auto& f = p.facets[k];
    for (const int i : f)
      if (i < 0 || i >= n) return facet_name(k) + " names vertex " + std::to_string(i) + ", not one of the " + std::to_string(n) + " vertices";
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) return facet_name(k) + " names a vertex twice";
    if (collinear(x[static_cast<std::size_t>(f[0])], x[static_cast<std::size_t>(f[1])], x[static_cast<std::size_t>(f[2])]))
      return facet_name(k) + " has collinear vertices";
  }
  if (p.facets.empty()) return std::string("no facets");
  std::optional<std::string> defect;
  closed_surface_defects(p.facets, [&](const SurfaceDefect& d) {
    if (defect) return;
    const std::string e = "edge (" + std::to_string(d.a) + ", " + std::to_string(d.b) + ")";
    using Kind = SurfaceDefect::Kind;
    if (d.kind == Kind::edge_count)
      defect = e + " is in " + std::to_string(d.count) + (d.count == 1 ? " facet: the surface is open" : " facets: it is not a 2-manifold");
    else if (d.kind == Kind::same_direction)
      defect = e + " runs the same way in its two facets: they are not oriented consistently";
    else
      defect = "vertex " + std::to_string(d.a) + " is pinched: its facets make " + std::to_string(d.count) + " cycles around it";
  });
  if (defect) return defect;
  Rational volume6 = 0;
  for (const auto& f : p.facets) {
    const P3 &o = x[0], &a = x[static_cast<std::size_t>(f[0])], &b = x[static_cast<std::size_t>(f[1])], &c = x[static_cast<std::size_t>(f[2])];
    volume6 += predicates::Orientation3Kernel::eval<Rational>({o.x, o.y, o.z, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z});  // det[a − o; b − o; c − o]
  }
  if (volume6 <= 0) return std::string("the facets are oriented inward (the enclosed volume is not positive): list each facet's vertices the other way");
  // Candidate pairs: bounding boxes in doubles widened beyond the rounding of the conversion.
  struct Box {
    std::array<double, 3> lo, hi;
  };
  const auto down = [](double v) { return v - std::abs(v) * 0x1p-50 - 0x1p-1000; };
  const auto up = [](double v) { return v + std::abs(v) * 0x1p-50 + 0x1p-1000; };
  std::vector<Box> box(p.facets.size());
  for (std::size_t k = 0; k < p.facets.size(); ++k) {
    box[k].lo = {INFINITY, INFINITY, INFINITY}, box[k].hi = {-INFINITY, -INFINITY, -INFINITY};
    for (const int i : p.facets[k]) {
      const auto& v = x[static_cast<std::size_t>(i)];
      const std::array<double, 3> c{v.x.convert_to<double>(), v.y.convert_to<double>(), v.z.convert_to<double>()};
      for (std::size_t d = 0; d < 3; ++d) {
        const bool finite = std::isfinite(c[d]);  // beyond the doubles: an unbounded box
        box[k].lo[d] = std::min(box[k].lo[d], finite ? down(c[d]) : -INFINITY), box[k].hi[d] = std::max(box[k].hi[d], finite ? up(c[d]) : INFINITY);
      }
    }
  }
  std::vector<std::size_t> order(p.facets.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return std::tie(box[i].lo[0], i) < std::tie(box[j].lo[0], j); });
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && box[order[j]].lo[0] <= box[order[i]].hi[0]; ++j) {
      const std::size_t t = std::min(order[i], order[j]), u = std::max(order[i], order[j]);
      if (box[t].lo[1] > box[u].hi[1] || box[u].lo[1] > box[t].hi[1] || box[t].lo[2] > box[u].hi[2] || box[u].lo[2] > box[t].hi[2]) continue;
      if (facets_meet(x, p.facets[t], p.facets[u])) return facet_name(t) + " and " + facet_name(u) + " intersect: the surface crosses itself";
    }
  return std::nullopt;
}

}  // namespace anisocert::geometry
