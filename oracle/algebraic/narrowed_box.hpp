#pragma once
// A filtered decision's second stage before the exact one (Shewchuk's adaptive stages, DESIGN.md
// § Numbers): the common point of two conics with rational coefficients that a double box holds
// alone, enclosed again to a few units in the last place. The double boxes of the filtered
// constructions (certified_roots.hpp) hold the common points of every pair of conics within the
// coefficients' double enclosures, so they are as wide as those enclosures make them (1e-13 of
// the domain is common). Here Krawczyk's operator (geometry/krawczyk.hpp) runs in MPFI at 128 bits
// on the exact conics, until it has proved the point unique in a box whose double rounding is
// no wider than a few ulps. Everything it returns is proved; when it cannot prove (a singular
// Jacobian: curves tangent there, or sharing a line through the box) it returns nothing, and the
// caller decides exactly.
#include "oracle/algebraic/bivariate.hpp"
#include "oracle/algebraic/located_point.hpp"

#include <optional>

namespace anisocert::oracle {

// A box of doubles holding the one common point of A and B that `box` holds (when `box` holds
// exactly one), within `box`, each side at most a few ulps wide; nothing when not proved.
std::optional<IntervalBox> narrowed_box(const Conic& A, const Conic& B, const IntervalBox& box);

}  // namespace anisocert::oracle
