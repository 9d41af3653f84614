#pragma once
// The Voronoi vertices of the true anisotropic Voronoi diagram D of a set of sites (LS §3: points
// where three sites are equally near and no site is nearer), in a box R, kept as sites are added.
// A binary tree of boxes over R whose every node lists the sites that can be nearest somewhere in
// its box (its candidates: a site is left out when its least squared distance over the box, bounded
// below, exceeds another site's greatest, bounded above, or when the difference of the two squared
// distances is positive over the box, against the two sites likeliest nearest there; the bounds
// are box_bounds.hpp's). A leaf with three candidates holds exactly the points equidistant
// from them (voronoi_vertex.hpp's certified boxes): no other site can be as near anywhere in it, so
// each is a vertex of D, of degree 3. A node with more is halved across its longer side in the
// candidates' metrics; once it is small beside their spacing it is resolved trio by trio instead
// (a point equidistant from three in the box is a vertex when every other candidate is certified
// strictly farther). A leaf is unresolved when a vertex of degree 4 or more, or sites too near to
// tell apart, lie there (down to `min_width`), or when three sites tie along a curve through it, or
// nearly (their search is undecided in a small leaf; see settle).
//
// Orphans and islands (LS Definition 1) need no special case: D is found wherever it is in R (with
// omega, in Ω and the leaves that meet it: see the constructor). Adding a
// site touches only the nodes where it is a candidate, which are near its cell. This is what the
// refiners that keep the true diagram use (LS §9 allows it: "The algorithm works equally well
// whether D is a true anisotropic Voronoi diagram or a loose anisotropic Voronoi diagram"; BWY
// keeps "only the Voronoi vertices inside Ω"). It is the refiners' own: the oracle's candidate
// subdivision (oracle/diagram/) is exact algebra, independent of this, and the tests compare the two.
#include "refiners/common/domain.hpp"
#include "refiners/common/certified_point.hpp"

#include <cmath>
#include <map>
#include <vector>

namespace anisocert::refiners::common {

class VertexSubdivision {
 public:
  struct Vertex {
    std::array<int, 3> sites;  // increasing
    VertexBox box;
    int holders = 0;  // leaves whose box found it; 0: no longer a vertex
  };

  // R: where vertices are kept; leaves are not split below min_width (> 0), nor once the tree
  // has 2²⁰ + 2¹¹ nodes per site or an insertion has made 2¹⁶ (then the leaf is unresolved: a
  // bound on memory and time, which a curve of ties, such as two sites at one point with different
  // metrics, would otherwise exhaust; the shock and radial runs of docs/refiners.md end with about
  // 40 nodes per site, and none of their insertions made more than 412).
  //
  // With omega, a leaf whose closed box misses closed Ω (Domain::contains, exactly) is left as it
  // is: neither resolved nor split, holding no vertex and not unresolved. The vertices kept are then
  // D's vertices in Ω and near it, which is what D|Ω needs, and ties outside Ω cost nothing: in an
  // L with the linear field, the sites on its right edge tie along a line through the notch, where
  // no site can break the tie, and the tree reached its bound on boxes after 32 sites.
  VertexSubdivision(const Box& R, double min_width, const Domain* omega = nullptr);

  // Adds site s as the next id (0, 1, 2, …).
  void insert(const MetricSite& s);

  const std::vector<MetricSite>& sites() const { return sites_; }
  // Every vertex ever found; those with holders > 0 are D's vertices in R, or with omega in the
  // leaves that meet Ω (and perhaps a little
  // beyond: a leaf's search may certify a point just outside its box).
  const std::vector<Vertex>& vertices() const { return vertices_; }
  // The vertices found by the last insertion, ordered by their sites, then by where they are.
  const std::vector<int>& created() const { return created_; }
  // The vertices the last insertion ended (their holders fell to 0), in the order it ended them.
  const std::vector<int>& released() const { return released_; }
  // The sites that can be nearest somewhere in b: the candidates of every leaf that meets b.
  std::vector<int> candidates_near(const Box& b) const;
  // The leaves where D could not be resolved (see above), with their candidates; empty when every
  // vertex in R (with omega, in the leaves that meet Ω) is known.
  struct Leaf {
    Box box;
    std::vector<int> candidates;
  };
  std::vector<Leaf> unresolved() const;
  bool resolved() const { return unresolved_leaves_ == 0; }
  // Whether a leaf was left unsplit because the tree reached its bound on nodes (above).
  bool full() const { return nodes_.size() + 2 > max_nodes() || nodes_.size() + 2 > insertion_start_ + max_nodes_per_insertion; }

 private:
  struct TrioSearch {
    std::array<int, 3> trio;  // increasing
    VertexSearch search;      // complete
  };
  struct Node {
    Box box;
    std::vector<int> candidates;  // a leaf's (an inner node keeps none)
    // An upper bound, over the box, of the squared distance to the nearest site: a leaf's least
    // upper bound of one site's d_u² on the box; an inner node's also the greatest of its children's.
    double least_greatest = INFINITY;
    int child = -1;  // the first of two consecutive children (halves), or −1 for a leaf
    std::vector<int> vertices;
    bool unresolved = false;
    // A leaf's complete vertex searches of its last resolution, trio by trio: they hold for its
    // box as long as the leaf is one, and for every box inside it (see resolve).
    std::vector<TrioSearch> searched;
  };

  // The sites of `from` (and `extra`, when ≥ 0) that can be nearest somewhere in b; U: the least
  // upper bound of their squared distances over b (a NaN bound counts as ∞).
  std::vector<int> candidates_in(const Box& b, const std::vector<int>& from, int extra, double& U) const;
  // Makes a node whose candidates are set a leaf with its vertices, or splits it; first_small:
  // false for the halves of a small node whose trios were tried already (see settle).
  void settle(int node, bool first_small = true, const std::vector<TrioSearch>& inherited = {});
  // The vertices of a leaf's candidates, three by three: each point equidistant from three in the
  // closed box from which every other candidate is strictly farther (certified_point.hpp). Kept
  // when every search and sign is decided; split when a fourth candidate may be as near (a vertex of
  // degree 4, or two vertices nearer than the box can tell); unresolved when a search is undecided
  // in a small leaf (`small`, see settle), or a vertex's place in the box or identity is.
  // A trio's search is looked up first in the node's own `searched`, then in `inherited`, the
  // searches of the ancestor that last resolved (boxes that hold the node's), and made only when
  // neither has it.
  enum class Resolution { resolved, split, unresolved };
  Resolution resolve(int node, bool small, const std::vector<TrioSearch>& inherited);
  void update(int node, int site);
  // Lowers an inner node's least_greatest to the greatest of its children's: every point of the
  // box lies in a child, where some site is that near. Far tighter than one site's bound on a
  // large box, so an insertion visits only the nodes near where its site can be nearest.
  void bound_by_children(int node);
  // Empties a leaf of vertices, appending the ids it held to `held`.
  void release(int leaf, std::vector<int>& held);
  int intern(const std::array<int, 3>& trio, const VertexBox& box);

  std::size_t max_nodes() const { return (std::size_t(1) << 20) + (std::size_t(1) << 11) * sites_.size(); }
  static constexpr std::size_t max_nodes_per_insertion = std::size_t(1) << 16;

  double min_width_;
  const Domain* omega_;
  std::vector<MetricSite> sites_;
  std::vector<Node> nodes_;
  std::vector<Vertex> vertices_;
  std::map<std::array<int, 3>, std::vector<int>> by_trio_;  // live vertices
  std::vector<int> created_, released_;
  int unresolved_leaves_ = 0;
  std::size_t insertion_start_ = 0;  // nodes before the last insertion
};

}  // namespace anisocert::refiners::common
