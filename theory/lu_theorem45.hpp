#pragma once
// Boissonnat, Wormser & Yvinec, "Locally uniform anisotropic meshing", Theorem 4.5 and the
// conditions of Lemmas 4.3–4.4 on the parameters (ρ₀, γ₀, δ, β), decided exactly.

#include "numbers/rational.hpp"

namespace anisocert::theory {

struct LuParameters {
  Rational rho0;    // radius-edge ratio bound ρ₀ > 0
  Rational gamma0;  // distortion bound γ₀ > 1
  Rational delta;   // picking ratio δ > 0
  Rational beta;    // size ratio β > 0
};

struct LuConditions {
  bool rho0_above_2;       // ρ₀ > 2                      (Theorem 4.5)
  bool delta_rho0;         // (1 − δ)³ ρ₀ > 2             (Theorem 4.5)
  bool delta_beta;         // (1 − δ)³ β > 2              (Theorem 4.5)
  bool lemma43;            // (1 − δ)³ ρ₀ > 2 γ₀³         (Lemma 4.3, Theorem 4.5)
  bool lemma44;            // (1 − δ)³ β > 2 γ₀³          (Lemma 4.4, Theorem 4.5)
  // Not decided here: Theorem 4.5's K(ρ₀, β) max(f(γ₀), g(γ₀), h(γ₀)) β² < (4/3) π δ², since the
  // paper gives no closed form for K, f, g, h (Lemmas 3.11–3.15 only bound them), and its
  // boundary-angle condition (> 90° at each boundary edge), a property of the domain and field.
  // all() is "every condition decided here holds", not "Theorem 4.5 applies".
  bool all() const { return rho0_above_2 && delta_rho0 && delta_beta && lemma43 && lemma44; }
};

// Throws std::invalid_argument naming the parameter outside the paper's ranges
// (γ₀ > 1, δ > 0, ρ₀ > 0, β > 0: LU §4.1).
LuConditions lu_t45_conditions(const LuParameters& p);

}  // namespace anisocert::theory
