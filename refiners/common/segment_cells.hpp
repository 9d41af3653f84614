#pragma once
// The cells a constrained subsegment s = ab meets (LS §9: s is encroached "if it intersects a
// Voronoi cell belonging to any site w other than a and b"), for sites that share one metric M,
// exactly. Along s, z(t) = a + t(b − a), every d_u(z)² − d_a(z)² is linear in t:
//   ℓ_u(t) = |u − a|²_M − 2t (b − a)ᵀM(u − a),
// so the part of s in u's closed cell is the closed range of t where ℓ_u is least: rational ends.
#include "numbers/rational.hpp"
#include "predicates/point.hpp"
#include "refiners/common/domain.hpp"

#include <optional>
#include <vector>

namespace anisocert::refiners::common {

using predicates::Point2;
using predicates::Sym2;

struct CellOnSegment {
  int site;
  Rational lo, hi;  // 0 <= lo <= hi <= 1: s ∩ Vor(site) = z([lo, hi]); lo = hi: a single point
  bool point() const { return lo == hi; }
};

// The closed cells among `sites` (a and b among them, each with its id) that meet s. Sites
// farther from s than |s|_M/2 (near_segment) or outside its diametral ellipse
// (outside_diametral_ellipse) never do: the caller may leave them out.
// Computed in doubles checked for rounding (numbers/exact_double.hpp), in expansions
// (numbers/expansion.hpp) when a double rounds, in rationals when an expansion overflows or
// underflows or `expansions` is false (the exact path the fast ones are tested against).
std::vector<CellOnSegment> cells_along(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M,
                                       const std::vector<std::pair<int, Point2<double>>>& sites, bool expansions = true);
// The cell of the site with id `site` alone, when it meets s: that of cells_along, without the
// others' (a third of the work when testing whether a new site would encroach).
std::optional<CellOnSegment> cell_along(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M,
                                        const std::vector<std::pair<int, Point2<double>>>& sites, int site, bool expansions = true);

// A box holding every point p whose M-distance to s is at most |s|_M / 2, the only sites that
// can be nearer to a point of s than both a and b (min(d_a, d_b)(z) <= |s|_M/2 on s): s widened
// by |s|_M/(2√λmin) ≤ √(|s|²_M/4 · trace/det), bounded above in FilterInterval; the whole plane
// when that bound is not finite.
common::Box near_segment(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M);

// A filter for the same: p lies certainly (FilterInterval) strictly outside s's diametral
// M-ellipse, d_p(m)² > |s|²_M/4 at the midpoint m. Then p is nowhere on s as near as the nearer of
// a and b: ℓ_p − min(ℓ_a, ℓ_b) is convex and piecewise linear on [0, 1], least at t = 0, ½ or 1,
// where it is |p − a|²_M, d_p(m)² − |s|²_M/4 and |p − b|²_M. False when the filter cannot tell.
// (With one metric this is Ruppert's diametral-circle test: LS encroachment in a Gabriel-protected
// subsegment.)
bool outside_diametral_ellipse(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M, const Point2<double>& p);

// LS §9's split point: the point of z([lo, hi]) nearest the "midpoint" t = `target` (d_a(z) =
// d_b(z): ½ for one metric), as a double exactly on s: a + j 2⁻ᵏ (b − a) with k the exact halvings
// of ab (at most 60) and 0 < j < 2ᵏ; on an axis-parallel s, whose every double between a and b
// lies on it, the double nearest z(target) when it lies in z([lo, hi]); nothing when [lo, hi]
// holds no such point.
std::optional<Point2<double>> split_point(const Point2<double>& a, const Point2<double>& b, const Rational& lo, const Rational& hi,
                                          const Rational& target = Rational(1, 2));

// The same with the fewest bits: of the points a + j 2⁻ᵏ (b − a) strictly between z(lo) and z(hi)
// within `slack` of `target` (strictly inside the window), one with the least k (an end of the
// range is a site when the range is a subsegment's). A split far from ½ then leaves subsegments that can be split
// again exactly (each split at 2⁻ᵏ spends k of the halvings a double allows). On an axis-parallel
// s, the double of fewest significant bits strictly inside the window.
std::optional<Point2<double>> coarse_split_point(const Point2<double>& a, const Point2<double>& b, const Rational& lo, const Rational& hi,
                                                 const Rational& target, const Rational& slack);

}  // namespace anisocert::refiners::common
