#pragma once
// The common points of two curves as located points, the one construction behind Voronoi
// vertices, ∂Ω crossings, vertical tangents and wedge-line meetings: filtered first (certified
// interval isolation, certified_roots.hpp, each point built exactly only if a decision needs it),
// exact (conic_intersection.hpp) when the intervals cannot decide or the filters are off.
#include "oracle/algebraic/certified_roots.hpp"

namespace anisocert::oracle {

struct CommonPoints {
  bool shared_component = false;   // then `points` is empty
  std::vector<LocatedPoint> points;  // sorted by x, then y
};

// Two curves known by enclosures of their coefficients, and how to build them exactly (only done
// when a decision needs it).
struct CurvePair {
  IntervalConic A, B;
  std::function<std::pair<Conic, Conic>()> exact;
};

// Every common point of the curves in `search`, perhaps with some beyond it (the exact path gives
// them all). Exact points' boxes are refined below `width`. Curves that share a component: the
// exact path reports `shared_component` (no points), and so does the filtered path when the
// shared curve meets `search` (no box along it can be certified or excluded, so it falls back);
// when the shared curve misses `search`, the filtered path gives the isolated points in `search`,
// the same points a caller finds from the shared line (shared_line.hpp).
CommonPoints common_points(const CurvePair& curves, const IntervalBox& search, const Rational& width);
CommonPoints common_points(const Conic& A, const Conic& B, const IntervalBox& search, const Rational& width);

// The same, exactly (today's path; for the rare callers that need every point).
CommonPoints exact_common_points(const Conic& A, const Conic& B, const Rational& width);

}  // namespace anisocert::oracle
