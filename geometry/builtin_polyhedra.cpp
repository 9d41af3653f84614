#include "geometry/builtin_polyhedra.hpp"

#include <cmath>
#include <numbers>

namespace anisocert::geometry {
namespace {

using P = predicates::Point3<Rational>;

// A multiple of 2⁻²⁰ nearest to t.
Rational on_grid(double t) { return Rational(static_cast<long>(std::lround(std::ldexp(t, 20))), 1L << 20); }

}  // namespace

Polyhedron cube_polyhedron() {
  Polyhedron p;
  for (int k = 0; k < 8; ++k) p.vertices.push_back(P{Rational(k & 1), Rational((k >> 1) & 1), Rational((k >> 2) & 1)});
  // Vertex k = (x, y, z) with x = bit 0, y = bit 1, z = bit 2; each face counter-clockwise from outside.
  p.facets = {{0, 2, 3}, {0, 3, 1},   // z = 0
              {4, 5, 7}, {4, 7, 6},   // z = 1
              {0, 1, 5}, {0, 5, 4},   // y = 0
              {2, 6, 7}, {2, 7, 3},   // y = 1
              {0, 4, 6}, {0, 6, 2},   // x = 0
              {1, 3, 7}, {1, 7, 5}};  // x = 1
  return p;
}

Polyhedron prism_polyhedron(const std::vector<std::array<Rational, 2>>& p, const Rational& h) {
  Polyhedron q;
  const int n = static_cast<int>(p.size());
  for (const Rational& z : {Rational(0), h})
    for (const auto& v : p) q.vertices.push_back(P{v[0], v[1], z});
  for (int i = 1; i + 1 < n; ++i) {
    q.facets.push_back({0, i + 1, i});
    q.facets.push_back({n, n + i, n + i + 1});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    q.facets.push_back({i, j, n + j});
    q.facets.push_back({i, n + j, n + i});
  }
  return q;
}

Polyhedron cube_cylinder_polyhedron(int segments) {
  // Per level z = 0 and z = 1: the arc's points from (0.5, 0) to (0, 0.5) (indices 0..n), then
  // (1, 0), (1, 1), (0, 1).
  Polyhedron p;
  const int n = segments, per = n + 4;
  for (int level = 0; level < 2; ++level) {
    for (int i = 0; i <= n; ++i) {
      const double t = std::numbers::pi / 2 * i / n;
      const Rational x = i == n ? Rational(0) : on_grid(0.5 * std::cos(t)), y = i == 0 ? Rational(0) : on_grid(0.5 * std::sin(t));
      p.vertices.push_back(P{x, y, Rational(level)});
    }
    p.vertices.push_back(P{Rational(1), Rational(0), Rational(level)});
    p.vertices.push_back(P{Rational(1), Rational(1), Rational(level)});
    p.vertices.push_back(P{Rational(0), Rational(1), Rational(level)});
  }
  const auto arc = [&](int level, int i) { return level * per + i; };
  const auto corner = [&](int level, int k) { return level * per + n + 1 + k; };  // k: 0 (1,0), 1 (1,1), 2 (0,1)
  // The z faces: fans from (1, 1) over the arc and the corners (the face is star-shaped from (1, 1)).
  for (int level = 0; level < 2; ++level) {
    std::vector<int> ring{corner(level, 0)};
    for (int i = 0; i <= n; ++i) ring.push_back(arc(level, i));
    ring.push_back(corner(level, 2));
    // The ring runs clockwise seen from +z around (1, 1): (1,0) → arc → (0,1).
    const int hub = corner(level, 1);
    for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
      if (level == 0) p.facets.push_back({hub, ring[k], ring[k + 1]});  // seen from −z: counter-clockwise
      else p.facets.push_back({hub, ring[k + 1], ring[k]});
    }
  }
  // The curved face, seen from the axis (outside Ω): strips between the arc's points.
  for (int i = 0; i < n; ++i) {
    p.facets.push_back({arc(0, i), arc(1, i), arc(1, i + 1)});
    p.facets.push_back({arc(0, i), arc(1, i + 1), arc(0, i + 1)});
  }
  // x = 1: (1,0), (1,1); y = 1: (1,1), (0,1); x = 0: (0,1), (0, 0.5); y = 0: (0.5, 0), (1, 0).
  const auto side = [&](int a0, int b0) {  // a quad a0 b0 b1 a1, counter-clockwise from outside when a → b runs so
    const int a1 = a0 + per, b1 = b0 + per;
    p.facets.push_back({a0, b0, b1});
    p.facets.push_back({a0, b1, a1});
  };
  side(corner(0, 0), corner(0, 1));
  side(corner(0, 1), corner(0, 2));
  side(corner(0, 2), arc(0, n));
  side(arc(0, 0), corner(0, 0));
  return p;
}

const Polyhedron* builtin_polyhedron(const std::string& name) {
  static const Polyhedron cube = cube_polyhedron(), cube_cylinder = cube_cylinder_polyhedron();
  if (name == "cube") return &cube;
  if (name == "cube-cylinder") return &cube_cylinder;
  return nullptr;
}

std::vector<std::string> builtin_polyhedron_names() { return {"cube", "cube-cylinder"}; }

}  // namespace anisocert::geometry
