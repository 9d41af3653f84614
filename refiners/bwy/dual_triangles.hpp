#pragma once
// BWY §3.2.2's set T, "the triangles dual to the Voronoi vertices lying in Ω", kept by edge as the
// vertices come and go: what rules 2, 4 and 5 and §3.2.1's local embedding ask of it. A triangle
// belongs to a key: a Voronoi vertex's id (one triangle), or a tie's (the fan of its polygon).
// Sites only: where they are is the refiner's.
#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace anisocert::refiners::bwy {

class DualTriangles {
 public:
  struct Triangle {
    std::array<int, 3> sites;  // counter-clockwise, unless flat
    bool flat;
    int key;
    bool alive;
  };

  // Adds a triangle of `key`.
  void add(int key, const std::array<int, 3>& sites, bool flat);
  // Removes the triangles of `key`; the edges (a < b) they leave in no triangle.
  std::vector<std::pair<int, int>> remove(int key);

  // The live triangles on edge ab (either order).
  const std::vector<int>& on_edge(int a, int b) const;
  bool is_edge(int a, int b) const { return !on_edge(a, b).empty(); }
  // The live triangles with the same three sites as t, t among them.
  const std::vector<int>& same_sites(int t) const;
  const Triangle& triangle(int t) const { return triangles_[static_cast<std::size_t>(t)]; }
  const std::vector<int>& of_key(int key) const;
  // Every live triangle, in the order they were added.
  std::vector<int> alive() const;
 private:
  static std::uint64_t edge_key(int a, int b);
  static std::array<int, 3> sorted(std::array<int, 3> s);

  std::vector<Triangle> triangles_;
  std::unordered_map<std::uint64_t, std::vector<int>> by_edge_;
  std::map<std::array<int, 3>, std::vector<int>> by_sites_;
  std::unordered_map<int, std::vector<int>> by_key_;
};

}  // namespace anisocert::refiners::bwy
