#pragma once
// sin²θ_bound as the LS properties compare angles with it: "angle ≥ arcsin √s2" proves "angle ≥
// θ_bound". Exactly 1/4 and 1/2 at 30° and 45° (closed forms), where an angle of exactly θ_bound
// is allowed (LS §9 refines angles "less than θ_bound") and right triangles in diag(l, 3l) have
// exactly 30°; otherwise a rational just above sin²θ_bound, from its certified enclosure.
#include "numbers/rational.hpp"
#include "theory/ls_theorem11.hpp"

#include <rapidcheck.h>

namespace anisocert::gen {

inline Rational sin2_above(double theta) {
  if (theta == 30) return Rational(1, 4);
  if (theta == 45) return Rational(1, 2);
  const Interval s = theory::ls_t11_sin_theta(rational_from_double(theta), 256);
  return rational_from_double(sqr(s).upper_double());
}

// θ_bound in tenths of a degree from `from` to `to` (both in tenths, inclusive), every value equally
// likely. rc::gen::inRange alone scales its range with the test's size, which grows over a run
// from 0: most runs would then take θ_bound near `from`, and the last few tenths of the range
// almost never (0 of 500 runs reached 20.8° of 5°–21°).
inline rc::Gen<double> theta_in_tenths(int from, int to) {
  return rc::gen::map(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(from, to + 1)), [](int t) { return t / 10.0; });
}

}  // namespace anisocert::gen
