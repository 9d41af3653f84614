#pragma once
// The star set of LU §3 in dimension 3 (issue 40), the twin of star_set.hpp: every site v keeps
// its star S_v, the tetrahedra at v of Del_{M_v} of the sites (perturbed symbolically where five
// are M_v-cospherical, predicates/insphere_perturbed.hpp), gift wrapped (gift_wrap3.hpp) among
// the sites within a reach and kept by Bowyer–Watson as sites are added (star_update3.hpp);
// restricted to Ω: the tetrahedra whose centroid Ω holds (all of them when Ω is convex). A
// conflict-zone index (the boxes of the M_v-circumspheres) finds the stars a new site may change.
// The candidate search is floating point (a reach in M_v-distance): a star is accepted when the
// circumsphere of every tetrahedron in Ω lies 10⁻⁴ inside the reach and every open face lies in
// the plane of one of Ω's facets; the reach grows fourfold until then, or until it holds every
// site; an open face of a tetrahedron outside Ω need not lie in a facet plane. (Tetrahedra
// outside Ω, across a non-convex Ω's hollows, have large spheres, and the hull of the candidates
// there is open anywhere; they are no part of the mesh. Requiring them to fit too made the
// cube-cylinder's stars search across the hollow: under UGAWG's linear field at h0 = 0.05 a run
// took 12.2 s, 5.6 s now, and its polar-1 field did not finish in 180 s, 43.6 s now, certified.) Beyond such a face
// lies outside Ω when Ω is convex there; past a reflex ridge sites of Ω may lie beyond it out of
// reach, and the conflict-zone index files the circumspheres only, not the half-spaces beyond the
// open faces: for a non-convex Ω a star on ∂Ω may then miss tetrahedra, which would lie outside Ω
// near that face. The certifier judges the mesh either way. A star made
// wrong by a missed candidate (rounding in the reach, beyond about 10⁶ : 1 anisotropy) makes the
// final mesh fail the certifier's exact local-uniformity check; it cannot go unnoticed.
#include "refiners/common/boundary3.hpp"
#include "refiners/star/gift_wrap3.hpp"
#include "refiners/star/star_update3.hpp"

#include <array>
#include <vector>

namespace anisocert::refiners::star {

class StarSet3 {
 public:
  StarSet3(const common::Domain3& domain, const common::Sites3& sites, const common::Boundary3& boundary);

  // A new site's (empty) star; its first search reaches M-distance √reach2 (0: the default).
  void add(double reach2);
  // S_v from scratch.
  void recompute(int v);
  // Bowyer–Watson on S_v for the new site k (Star3Update::recompute: call recompute).
  Star3Update update(int v, int k);
  // The stars whose conflict zone's box holds q, by increasing site.
  const std::vector<int>& near(const predicates::Point3<double>& q) const { return zones_.holding(q, sites_.grid); }
  // After the site grid was rebuilt.
  void refile() { zones_.refile(sites_.grid); }

  std::size_t size() const { return stars_.size(); }
  const Star3& star(int v) const { return stars_[v].star; }
  // Whether S_v's i-th tetrahedron is in Ω.
  bool in_domain(int v, std::size_t i) const { return stars_[v].in_domain[i]; }
  // The sites of S_v's link, sorted.
  const std::vector<int>& neighbours(int v) const { return stars_[v].neighbours; }
  // Whether S_v has the tetrahedron of v and the three sites of `others` in Ω (any order).
  bool has_tetrahedron(int v, std::array<int, 3> others) const;
  // Tetrahedra in Ω in the stars of all four of their vertices (LU: consistent), each once,
  // positively oriented; `inconsistent`: star tetrahedra in Ω that are not.
  std::vector<std::array<int, 4>> consistent_tetrahedra(std::size_t& inconsistent) const;
  // Sites whose star has no tetrahedron in Ω.
  std::size_t empty_stars() const;

 private:
  struct Entry {
    Star3 star;
    std::vector<char> in_domain;
    std::vector<int> neighbours;
    double reach2 = 0;
  };
  // in_domain, neighbours, and the conflict zone's box; returns whether the star fits `reach2`.
  bool refresh(int v, double reach2);

  const common::Domain3& domain_;
  const common::Sites3& sites_;
  const common::Boundary3& boundary_;
  std::vector<Entry> stars_;
  common::FiledBoxes3 zones_;
  bool convex_;
  std::vector<int> cand_;
};

}  // namespace anisocert::refiners::star
