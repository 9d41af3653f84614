#pragma once
// The apexes of small input angles: vertices of the PSLG X (Ω's corners and its points) where two
// of its segments (Ω's edges and the interior segments) meet at less than 60° in the vertex's
// metric M_c. Around them the refiners carry two devices of Delaunay refinement for small input
// angles to the metric:
//   concentric shells (J. Ruppert, "A Delaunay refinement algorithm for quality 2-dimensional
//     mesh generation", J. Algorithms 18, 1995: "modified segment splitting using concentric
//     circular shells"): a subsegment with exactly one end at an apex is split at a power-of-two
//     M_c-distance from it, between a third and two thirds of the subsegment, and the apex's
//     subsegments are first split at one such distance, at most half the shortest (corner
//     lopping). Splits on the segments then come at the same distances, where none encroaches
//     another's subsegment, and the splits do not ping-pong towards the apex;
//   the skinny triangles "across" a small input angle are left alone (G. L. Miller, S. E. Pav and
//     N. J. Walkington, "When and why Ruppert's algorithm works", 12th International Meshing
//     Roundtable, 2003; Shewchuk's Triangle leaves a triangle whose shortest edge joins two
//     segment vertices at the same distance from the segments' common apex): the shape rules do
//     not split a triangle whose shortest edge joins split sites on two segments that meet at
//     less than 60° at an apex, on one shell. Its circumcentre encroaches those segments, and
//     splitting them makes the next such triangle, down to the apex.
// LS (on Del_M and on the true diagram) and BWY use them. Which vertices are apexes and where a
// shell lies are choices in doubles; the exemption is decided exactly.
#include "refiners/common/domain.hpp"
#include "refiners/common/subsegments.hpp"

#include <array>
#include <deque>
#include <optional>
#include <vector>

namespace anisocert::refiners::common {

class CornerShells {
 public:
  // metrics[k]: the metric of X's vertex k, which is site k of the refiner. Keeps a reference to domain.
  CornerShells(const Domain& domain, std::vector<predicates::Sym2<double>> metrics);

  bool sharp(int k) const { return k >= 0 && k < static_cast<int>(sharp_.size()) && sharp_[static_cast<std::size_t>(k)]; }
  // Where a split of subsegment ab (sites a and b at `points`) aims: its parameter from a on the
  // shell, when exactly one end is an apex; else nothing (the refiner's own midpoint).
  std::optional<double> parameter(int a, int b, const std::vector<Point2<double>>& points) const;
  // The corner lopping: for each apex c and each segment from it to vertex o, the parameter from c
  // of the first split of the subsegment co (while it is whole).
  struct Shell {
    int c, o;
    double t;
  };
  std::vector<Shell> first() const;
  // The next first shell still to split, in first()'s order: its subsegment and its point, within
  // slack() of the subsegment of the shell, the coarsest double of its grid (coarse_split_point).
  // A shell whose subsegment is split already, or holds no such double, is passed over; nothing
  // when none is left.
  struct Split {
    int s;
    Point2<double> z;
  };
  std::optional<Split> next_first_shell(const Subsegments& subsegments, const std::vector<Point2<double>>& points);
  // The point of a split of subsegment s on its shell, when one end is an apex (parameter()):
  // within slack() of the subsegment of the shell, the coarsest double of its segment's grid, in
  // whichever cell it falls (so that later splits stay exact); nothing otherwise, or when the grid
  // has no double there.
  std::optional<Point2<double>> shell_point(const Subsegments& subsegments, int s, const std::vector<Point2<double>>& points) const;
  // How near its shell a split lies, as a share of the subsegment. Equal shells on two segments at
  // an angle θ in the metric keep clear of each other's subsegments by about θ²/2 of their distance
  // (3.4·10⁻³ at 4.8°: √(5/4 − cos θ) − ½); within 1/64, and moved into an encroacher's cell, the
  // shells of a 4.8° corner ended 0.4–1.6% apart and the ping-pong started again. 2⁻²⁰ keeps clear
  // down to about 0.1°, at 20 more bits per split near the apex.
  static Rational slack() { return Rational(1, 1 << 20); }
  // The exemption for the triangle of sites t: its shortest edge in M_c (none shorter) joins two
  // split sites (no vertex of X) on two segments meeting at apex c at less than 60° in M_c, whose
  // squared M_c-distances from c differ by at most 2⁻¹⁰ of either (one shell: the shells lie
  // within 2⁻²⁰ of the subsegment of theirs). Exact.
  bool exempt(const std::array<int, 3>& t, const std::vector<Point2<double>>& points) const;

 private:
  struct Apex {
    int c;
    std::vector<int> ends;                     // the other ends of the segments at c
    std::vector<std::pair<int, int>> narrow;  // the pairs of them at less than 60° in M_c
  };
  double distance(int c, const Point2<double>& p) const;

  const Domain& domain_;
  std::vector<predicates::Sym2<double>> metrics_;
  std::vector<char> sharp_;
  std::vector<Apex> apexes_;
  std::deque<Shell> lopping_;  // the first shells still to split
};

}  // namespace anisocert::refiners::common
