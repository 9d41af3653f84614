#pragma once
// Two conics that share a line: A = G·H1 and B = G·H2 for a rational line G. Their common points
// are all of G and the points of H1 ∩ H2; only the latter can be isolated. Bisectors of three
// sites share a line when the sites tie along it (equal metrics, symmetric positions).
#include "oracle/algebraic/conic_intersection.hpp"

#include <optional>
#include <vector>

namespace anisocert::oracle {

// F = L·Q for a line L = d x + e y + f with e ≠ 0 that divides the conic F.
Conic line_quotient(const Conic& F, const Conic& L);
// The rational line shared by two conics that share a component and are not proportional: the
// common root of their restrictions to two vertical lines x = t (each a quadratic in y, since no
// sheared curve is vertical), or nothing when every restriction has both roots in common.
std::optional<Conic> common_line(const Conic& A, const Conic& B);
// The isolated common points of A and B, sorted by x then y: all of intersect(A, B)'s when they
// share no component; when they share a line G, those of H1 ∩ H2 off G; none when A and B are
// proportional or one of them is G. Throws std::domain_error when they share a component that
// common_line does not find.
std::vector<AlgebraicPoint> isolated_common_points(const Conic& A, const Conic& B);

}  // namespace anisocert::oracle
