#pragma once
// sin²θ_bound as the LS properties compare angles with it: "angle ≥ arcsin √s2" proves "angle ≥
// θ_bound". Exactly 1/4 and 1/2 at 30° and 45° (closed forms), where an angle of exactly θ_bound
// is allowed (LS §9 refines angles "less than θ_bound") and right triangles in diag(l, 3l) have
// exactly 30°; otherwise a rational just above sin²θ_bound, from its certified enclosure.
#include "numbers/rational.hpp"
#include "theory/ls_theorem11.hpp"

namespace anisocert::gen {

inline Rational sin2_above(double theta) {
  if (theta == 30) return Rational(1, 4);
  if (theta == 45) return Rational(1, 2);
  const Interval s = theory::ls_t11_sin_theta(rational_from_double(theta), 256);
  return rational_from_double(sqr(s).upper_double());
}

}  // namespace anisocert::gen
