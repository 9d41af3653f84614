#pragma once
// The small diagram inputs of the diagram harnesses, decoded from bytes: up to 6 sites on the
// grid of eighths, metrics M = FᵀF with F = [[a, b], [0, c]] of small integers (up to 4:1
// anisotropy), in a square, a triangle or an L-shaped domain (non-convex). The grid makes ties,
// cocircular sites and sites on ∂Ω and its corners common.
// Bytes: number of sites, shape (0 square, 1 triangle, 2 L), then x, y (eighths), a, b, c per site.
#include "geometry/mesh.hpp"

#include <cstddef>
#include <cstdint>

namespace anisocert::fuzz {

enum class Shape { square, triangle, l_shape };

// The longest input that adds anything.
constexpr std::size_t small_diagram_max_len = 2 + 5 * 6;

// p ∈ Ω (closed), for the three shapes of the unit square.
bool inside(const predicates::Point2<Rational>& p, Shape s);

// The input, or nothing (no site) when size < 2 or no site lies in Ω.
struct SmallDiagram {
  Shape shape = Shape::square;
  geometry::Mesh<Rational> input;
};
SmallDiagram small_diagram(const std::uint8_t* data, std::size_t size);

}  // namespace anisocert::fuzz
