#include "fuzz/support/small_diagram.hpp"

#include <algorithm>

namespace anisocert::fuzz {

namespace {

geometry::Polygon<Rational> domain(Shape s) {
  const Rational h(1, 2);
  switch (s) {
    case Shape::triangle: return {{0, 0}, {1, 0}, {0, 1}};
    case Shape::l_shape: return {{0, 0}, {1, 0}, {1, h}, {h, h}, {h, 1}, {0, 1}};
    default: return {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  }
}

}  // namespace

bool inside(const predicates::Point2<Rational>& p, Shape s) {
  const Rational h(1, 2);
  if (p.x < 0 || p.y < 0 || p.x > 1 || p.y > 1) return false;
  if (s == Shape::triangle) return p.x + p.y <= 1;
  if (s == Shape::l_shape) return p.x <= h || p.y <= h;
  return true;
}

SmallDiagram small_diagram(const std::uint8_t* data, std::size_t size) {
  SmallDiagram out;
  if (size < 2) return out;
  out.shape = static_cast<Shape>(data[1] % 3);
  out.input.domain = domain(out.shape);
  const std::size_t wanted = 1 + data[0] % 6;
  for (std::size_t at = 2; at + 5 <= size && out.input.sites.size() < wanted; at += 5) {
    const predicates::Point2<Rational> p{Rational(data[at] % 9, 8), Rational(data[at + 1] % 9, 8)};
    if (!inside(p, out.shape)) continue;
    if (std::any_of(out.input.sites.begin(), out.input.sites.end(), [&](const auto& q) { return q.x == p.x && q.y == p.y; }))
      continue;
    const Rational a(1 + data[at + 2] % 4), b(static_cast<int>(data[at + 3] % 7) - 3), c(1 + data[at + 4] % 4);
    out.input.sites.push_back(p);
    out.input.metrics.push_back({a * a, a * b, b * b + c * c});
  }
  return out;
}

}  // namespace anisocert::fuzz
