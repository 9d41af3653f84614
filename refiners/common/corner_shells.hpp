#pragma once
// Ω's sharp corners, those whose two edges meet at less than 60° in the corner's metric M_c, and
// the two devices of Delaunay refinement for small input angles, carried to the metric:
//   concentric shells (J. Ruppert, "A Delaunay refinement algorithm for quality 2-dimensional
//     mesh generation", J. Algorithms 18, 1995; Shewchuk's "modified segment splitting"): a
//     subsegment with exactly one end at a sharp corner is split at a power-of-two M_c-distance
//     from the corner, between a third and two thirds of it, and each sharp corner's two
//     subsegments are first split at one such distance, at most half the shorter (corner
//     lopping). Splits on the two edges then come at the same distances, where neither encroaches
//     the other's subsegment, and the splits do not ping-pong towards the corner;
//   the small-angle exemption (J. R. Shewchuk, "Delaunay refinement algorithms for triangular
//     mesh generation", Comput. Geom. 22, 2002, on small input angles; his Triangle does the
//     same): a triangle whose shortest edge joins a site on each of a sharp corner's two edges is
//     skinny because of the input angle, and the shape rules leave it alone. Its circumcentre
//     encroaches those edges, whose splits would make the next such triangle, down to the corner.
// Every refiner that splits subsegments uses them (LS on Del_M, LS and BWY on the true diagram).
// Which corners are sharp and where a shell lies are choices in doubles; the exemption is decided
// exactly.
#include "refiners/common/domain.hpp"

#include <array>
#include <optional>
#include <vector>

namespace anisocert::refiners::common {

class CornerShells {
 public:
  // metrics[k]: the metric of Ω's corner k, which is site k of the refiner.
  CornerShells(const Domain& domain, std::vector<predicates::Sym2<double>> metrics);

  bool sharp(int k) const { return k >= 0 && k < static_cast<int>(sharp_.size()) && sharp_[static_cast<std::size_t>(k)]; }
  // Where a split of subsegment ab (sites a and b at `points`) aims: its parameter from a on the
  // shell, when exactly one end is a sharp corner; else nothing (the refiner's own midpoint).
  std::optional<double> parameter(int a, int b, const std::vector<Point2<double>>& points) const;
  // The corner lopping: for each sharp corner c and each of its edges to corner o, the parameter
  // from c of the first split of the subsegment co (while it is whole).
  struct Shell {
    int c, o;
    double t;
  };
  std::vector<Shell> first() const;
  // How near its shell a split lies, as a share of the subsegment. Equal shells on the two edges
  // keep clear of each other's subsegments by a margin of about θ²/8 of the distance at a corner of
  // θ in the metric (2.6·10⁻⁴ at 4.6°, where 1/64 made the ping-pong start again); 2⁻²⁰ keeps
  // clear down to about 0.2°, at 20 more bits per split near the corner.
  static Rational slack() { return Rational(1, 1 << 20); }
  // The exemption for the triangle of sites t: its shortest edge in M_c (none shorter) joins a
  // site other than c on one edge of a sharp corner c and one on the other, whose M_c-distances
  // from c are within a factor √2 (the same shell, give or take where a split could go; the next
  // shell is twice as far). Exact.
  bool exempt(const std::array<int, 3>& t, const std::vector<Point2<double>>& points) const;

 private:
  double distance(int c, const Point2<double>& p) const;

  const Domain& domain_;
  std::vector<predicates::Sym2<double>> metrics_;
  std::vector<char> sharp_;
  std::vector<int> sharp_list_;
};

}  // namespace anisocert::refiners::common
