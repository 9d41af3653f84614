#pragma once
// The common points of two curves (conics or lines) in a box, isolated in double-precision
// interval arithmetic (issue 14): Krawczyk's operator (Krawczyk 1969; Moore 1977) on the 2×2
// system A = B = 0, with bisection and exclusion. For a box X, a point m ∈ X and any matrix C,
//   K(X) = m − C·F(m) + (I − C·J(X))·(X − m)
// contains every root of F in X; K(X) ∩ X = ∅ proves X root-free, and K(X) ⊂ int X proves
// exactly one root in X. A box where 0 ∉ A(X) or 0 ∉ B(X) is root-free. If every matrix of the
// interval Jacobian J(H) on a convex H is non-singular (0 ∉ det J(H)), F is one-to-one on H (mean
// value theorem, row by row), so H holds at most one root: this merges two certified boxes of the
// same root, and lets a root certified in a small box Y around a Newton iterate account for a
// whole box X when H = hull(X ∪ Y).
//
// The answer is either complete — pairwise disjoint boxes, each holding exactly one common point,
// and together every common point in the search box (some boxes may reach outside it, never
// beyond the search box enlarged by its width on each side, since a root certified around a
// Newton iterate from a sub-box X counts only when the iterate is within X's width of X) — or
// nothing, when the intervals cannot decide: tangential or nearly tangential meetings, shared
// components, overflow, or a search box with an infinite side. The caller then uses the exact
// intersection (conic_intersection.hpp).
#include "oracle/algebraic/located_point.hpp"

#include <optional>
#include <vector>

namespace anisocert::oracle {

// A conic known by enclosures of its coefficients a x² + b xy + c y² + d x + e y + f.
struct IntervalConic {
  FilterInterval a, b, c, d, e, f;
  static IntervalConic around(const Conic& G);
};

// The common points of every pair of conics in the enclosures: the exact curves' are among them.
std::optional<std::vector<IntervalBox>> certified_common_roots(const IntervalConic& A, const IntervalConic& B,
                                                               const IntervalBox& search);

}  // namespace anisocert::oracle
