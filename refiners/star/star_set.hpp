#pragma once
// The star set of LU §3 (Definition 3.1): every site v keeps its star S_v, the triangles incident
// to v in Del_{M_v}(V) restricted to Ω, found by gift wrapping around v with exact in-circle
// tests in M_v (gift_wrap.hpp), and updated when a new site falls in its conflict zone Z_v (the
// union of the circumellipses of its triangles, LU Lemma 3.5: Z_v only shrinks). A conflict-zone
// index over the grid finds the stars a new site may change.
#include "refiners/common/boundary.hpp"

#include <array>
#include <vector>

namespace anisocert::refiners::star {

using predicates::Point2;
using predicates::Sym2;

struct Star {
  std::vector<std::array<int, 2>> triangles;  // (a, b): triangle (v, a, b) counter-clockwise, in Ω
  std::vector<std::array<int, 2>> outside;    // the rest of v's Delaunay fan, outside Ω
  std::vector<int> neighbours;                // sorted
  common::Cells cells;                        // grid cells filed under (the conflict zone's box)
  common::Box zone;                           // the conflict zone's bounding box (empty: x0 > x1)
};

class StarSet {
 public:
  StarSet(const common::Domain& domain, const common::Sites& sites, const common::Boundary& boundary);

  // A new site's (empty) star; its first search reaches M-distance √reach2 (0: the default).
  void add(double reach2);
  // S_v from scratch.
  void recompute(int v);
  // Bowyer–Watson on S_v for the new site k.
  enum class Update { unchanged, updated, recompute };
  Update update(int v, int k);
  // The stars whose conflict zone's box may hold q (to be tested with zone_holds).
  const std::vector<int>& near(const Point2<double>& q) const { return index_.at(sites_.grid.cell_of(q)); }
  // (The box the index filed v under, not just its cells.)
  bool zone_holds(int v, const Point2<double>& q) const { return stars_[v].zone.contains(q); }
  // Files every star's conflict zone again (after the grid was rebuilt).
  void refile();

  const Star& operator[](int v) const { return stars_[v]; }
  std::size_t size() const { return stars_.size(); }
  // (a, b, c) is a triangle of S_a, as (a, b, c) in its counter-clockwise order.
  bool has_triangle(int a, int b, int c) const {
    for (const auto& u : stars_[a].triangles)
      if (u[0] == b && u[1] == c) return true;
    return false;
  }
  // The triangles that are in the stars of all three of their vertices (LU: consistent), each once
  // with its least site first, and how many star triangles are not.
  std::vector<std::array<int, 3>> consistent_triangles(std::size_t& inconsistent) const;

 private:
  void refresh_zone(int v);
  void set_zone(int v, const common::Box& zone);
  // Whether a star triangle (v, a, b) lies in Ω (see star_set.cpp).
  bool triangle_in_domain(int v, int a, int b) const;

  const common::Domain& domain_;
  const common::Sites& sites_;
  const common::Boundary& boundary_;
  std::vector<Star> stars_;
  std::vector<double> reach2_;  // per site: the squared M_v-reach of its star
  common::BoxIndex index_;
  // Scratch buffers, reused (allocation was a third of the time).
  std::vector<int> cand_, ring_;
  std::vector<char> in_;
  std::vector<std::array<int, 2>> fan_;
};

}  // namespace anisocert::refiners::star
