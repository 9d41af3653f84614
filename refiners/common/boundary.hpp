#pragma once
// The edge level of every refiner (CGAL Mesh_2's Refine_edges; LU §4.1 rule 1, LS §9, BWY §3.2.2
// rule 1): the constrained subsegments, initially the edges of Ω, split at their exact midpoints
// while a site encroaches them (on an axis-parallel subsegment whose midpoint is no double, at the
// double on it nearest the midpoint: segment_cells.hpp's split_point; a mesh's boundary vertices
// have all 53 bits, `refine --from`); and LU §4.1's Insert_or_snap: a point a
// refiner wants to insert that lies outside Ω or encroaches a subsegment splits that subsegment
// instead.
//
// Encroachment (LU Definition 3.16) is decided by the exact predicate, in the metric of the point
// and of each endpoint. Which subsegments are tested is chosen by boxes in doubles (a prefilter
// twice the endpoints' diametral ellipses; for a point whose own metric is much weaker than the
// endpoints' it can miss an encroachment in that metric): this selects where a refiner inserts,
// not what it claims; whether the final mesh is valid and locally uniform is the certifier's
// exact verdict.
#include "refiners/common/sites.hpp"

#include <array>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace anisocert::refiners::common {

class Boundary {
 public:
  // The corners of `domain` must be sites 0 … m − 1 of `sites`, in order.
  Boundary(const Domain& domain, Sites& sites);

  const std::vector<std::pair<int, int>>& segments() const { return segments_; }
  // v's two neighbours along ∂Ω, or {−1, −1} when v is not on ∂Ω.
  const std::array<int, 2>& neighbours(int v) const { return neighbours_[v]; }
  bool on_boundary(int v) const { return neighbours_[v][0] >= 0; }
  bool is_segment(int a, int b) const { return neighbours_[a][0] == b || neighbours_[a][1] == b; }

  // LU Definition 3.16: x strictly inside the diametral ellipse of subsegment s in x's metric or
  // in an endpoint's (exact; x outside s's prefilter box does not encroach).
  bool encroaches(const Point2<double>& x, const Sym2<double>& Mx, int s) const;

  // To be called after every new site: files the boxes of the subsegments a split just created.
  void site_added();
  // Queues the subsegments site k encroaches.
  void queue_encroached_by(int k);
  // Files every subsegment's box again (after the grid was rebuilt).
  void refile();

  // The edge level: the next queued subsegment that a site still encroaches, or nothing.
  std::optional<int> next_encroached();
  // Splitting subsegment s: its exact midpoint (or, axis-parallel, the double nearest it), to be
  // inserted as the next site, or, when s has no such point, why refinement cannot go on (naming
  // the nearest corner and whether LU Lemma 4.1 fails there). Then end_split queues the halves a
  // site still encroaches.
  std::variant<Point2<double>, std::string> begin_split(int s);
  void end_split(int s);
  std::size_t queued() const { return queue_.size(); }

  // Insert_or_snap for a point x picked to refine the triangle with centroid g, in the triangle's
  // metric M (x's own is Mx): the subsegment to split instead of inserting x, if any: one x
  // encroaches (in M, Mx or an endpoint's metric), or when x lies outside Ω the one crossed by the
  // segment from g to x (else the one nearest to x in M, a floating-point choice).
  std::optional<int> snap(const Point2<double>& x, const Sym2<double>& M, const Sym2<double>& Mx, const Point2<double>& g) const;

  // LU Lemma 4.1 needs every corner's angle > 90° in its metric; false at corner k when it is not:
  // (a − c)ᵀ M_c (b − c) ≥ 0 for its neighbours a, b (exact).
  bool corner_is_obtuse(std::size_t k) const;

 private:
  bool encroached_by_site(int p, int s) const;
  // The box (a prefilter) outside which no point encroaches s in its endpoints' metrics, doubled so
  // that it also serves a nearby point's own (similar) metric; filed in the grid cells it covers.
  void set_box(int s);
  // A box around subsegment s, of half-width its longer side, searched for the sites that still
  // encroach it. A heuristic: in an anisotropic metric a site outside it can encroach s (M =
  // diag(1, 1/100), s from (0, 0) to (1, 0): (1/2, 3) does), and s is then not split; searching
  // the diametral boxes instead changes 6 of 13 reference runs, so it is left for a change of
  // its own.
  Box search_box(int s) const;

  const Domain& domain_;
  Sites& sites_;
  std::vector<std::pair<int, int>> segments_;
  std::vector<std::array<int, 2>> neighbours_;
  FiledBoxes boxes_;
  std::vector<int> pending_;  // subsegments whose boxes wait for the new site's metric
  std::deque<int> queue_;
};

}  // namespace anisocert::refiners::common
