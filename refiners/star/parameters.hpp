#pragma once
// The star refiner's parameters (LU Theorem 4.5's ρ₀, γ₀, δ, β; `size`; Pick_valid's attempts),
// with the budgets and the seed every run has.
#include "refiners/common/result.hpp"

namespace anisocert::refiners::star {

struct RefineParameters : common::Budget {
  double rho0 = 3, gamma0 = 1.5, delta = 0.1, beta = 3, size = 1;
  // Pick_valid: how many picked points may be discarded as γ₀-cocircular before one is kept
  // (0 turns the test off). The test is only selective for γ₀ near 1, as LU Theorem 4.5 assumes.
  int pick_attempts = 3;
  // 3D: begin with sites inside Ω about `size` apart in the metric (star_refiner3.cpp).
  bool seed_interior = true;
  unsigned seed = 1;
};

}  // namespace anisocert::refiners::star
