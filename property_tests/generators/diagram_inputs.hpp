#pragma once
// RapidCheck generators of whole inputs of the exact diagram (oracle/diagram.hpp).
#include "oracle/diagram/diagram.hpp"

#include <rapidcheck.h>

#include <string>

namespace anisocert::gen {

struct DiagramCase {
  oracle::Mesh<Rational> input;
  std::string kind;  // the metric class, for RC_TAG
};

// 2 to 8 distinct sites with coordinates k/64 in the open unit square (its domain), with metrics
// of one class: "constant" (one M = FᵀF for all, LS: always wedged), "nearly_constant"
// (F + E/20 per site) or "varied" (independent F per site, axis ratios up to 10).
rc::Gen<DiagramCase> diagram_case();

// A Theorem 7 setting: the unit square's corners and 0 to 3 equally spaced points per side are
// both sites and domain vertices (so every domain edge joins two sites), plus 1 to 5 interior
// sites in [3/10, 7/10]², with "constant" or "nearly_constant" metrics.
rc::Gen<DiagramCase> theorem7_case();

std::ostream& operator<<(std::ostream& os, const DiagramCase& c);

}  // namespace anisocert::gen
