#pragma once
// RapidCheck generators of exact rationals and of the papers' parameters, with the
// degeneracy classes that matter for each statement (DESIGN.md § Tests).

#include "numbers/rational.hpp"

#include <rapidcheck.h>

#include <string>

namespace anisocert::gen {

// A rational strictly between lo and hi: lo + (hi − lo)·k/n, with n a power of ten (short
// decimals) or an arbitrary integer up to 10⁶ (fractions). Shrinks toward lo.
rc::Gen<Rational> rational_in(const Rational& lo, const Rational& hi);

// θ_bound in degrees, 0 <= θ < θ_max of LS Theorem 11, tagged with its class:
// "zero", "integer", "decimal_or_fraction", or "near_max" (θ_max truncated to 1..70 decimals).
struct Theta {
  Rational value;
  std::string kind;
};
rc::Gen<Theta> admissible_theta();

// θ_max of LS Theorem 11 truncated to `decimals` digits after the point (a rational < θ_max).
Rational theta_max_truncated(int decimals);

// 10^-k
Rational ten_to_minus(int k);

// RapidCheck prints counterexamples with operator<<.
std::ostream& operator<<(std::ostream& os, const Theta& t);

}  // namespace anisocert::gen
