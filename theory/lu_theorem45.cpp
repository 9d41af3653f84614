#include "theory/lu_theorem45.hpp"

#include <stdexcept>

namespace anisocert::theory {

LuConditions lu_t45_conditions(const LuParameters& p) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(what);
  };
  require(p.rho0 > 0, "rho0 must be > 0 (LU §4.1)");
  require(p.gamma0 > 1, "gamma0 must be > 1 (LU §4.1)");
  require(p.delta > 0, "delta must be > 0 (LU §4.1)");
  require(p.beta > 0, "beta must be > 0 (LU §4.1)");
  const Rational shrink = (1 - p.delta) * (1 - p.delta) * (1 - p.delta);
  const Rational two_gamma0_cubed = 2 * p.gamma0 * p.gamma0 * p.gamma0;
  return LuConditions{
      .rho0_above_2 = p.rho0 > 2,
      .delta_rho0 = shrink * p.rho0 > 2,
      .delta_beta = shrink * p.beta > 2,
      .lemma43 = shrink * p.rho0 > two_gamma0_cubed,
      .lemma44 = shrink * p.beta > two_gamma0_cubed,
  };
}

}  // namespace anisocert::theory
