// LU Theorem 4.5 (locally uniform anisotropic meshing): the parameter conditions, their
// implications, exact boundaries and monotonicity in δ.

#include "property_tests/generators/rationals.hpp"
#include "theory/lu_theorem45.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using anisocert::gen::rational_in;
using anisocert::gen::ten_to_minus;
using namespace anisocert::theory;

namespace {

struct Tagged {
  LuParameters p;
  std::string kind;
};

// Generic parameters, and the exact boundary (1 − δ)³ρ₀ = 2γ₀³ of Lemma 4.3.
rc::Gen<Tagged> lu_parameters() {
  auto generic = rc::gen::apply(
      [](Rational rho0, Rational gamma0, Rational delta, Rational beta) {
        return Tagged{{rho0, gamma0, delta, beta}, "generic"};
      },
      rational_in(Rational(0), Rational(20)), rational_in(Rational(1), Rational(2)),
      rational_in(Rational(0), Rational(1)), rational_in(Rational(0), Rational(20)));
  auto boundary = rc::gen::map(generic, [](Tagged t) {
    const Rational shrink = (1 - t.p.delta) * (1 - t.p.delta) * (1 - t.p.delta);
    t.p.rho0 = 2 * t.p.gamma0 * t.p.gamma0 * t.p.gamma0 / shrink;
    t.kind = "lemma43_boundary";
    return t;
  });
  return rc::gen::oneOf(generic, boundary);
}

}  // namespace

RC_GTEST_PROP(LU_T45, ConditionsImplyTheTheoremsWeakerOnes, ()) {
  const Tagged t = *lu_parameters();
  RC_TAG(t.kind);
  const LuConditions c = lu_t45_conditions(t.p);
  RC_CLASSIFY(c.all(), "all hold");
  // γ₀ > 1 ⇒ 2γ₀³ > 2, so Lemmas 4.3/4.4's conditions imply (1−δ)³ρ₀ > 2 and (1−δ)³β > 2.
  if (c.lemma43) RC_ASSERT(c.delta_rho0);
  if (c.lemma44) RC_ASSERT(c.delta_beta);
  if (c.delta_rho0) RC_ASSERT(c.rho0_above_2);  // (1−δ)³ <= 1 for δ > 0
  if (t.kind == "lemma43_boundary") {
    RC_ASSERT(!c.lemma43);  // strict inequality at equality
    LuParameters above = t.p;
    above.rho0 += ten_to_minus(40);
    RC_ASSERT(lu_t45_conditions(above).lemma43);
  }
}

RC_GTEST_PROP(LU_T45, SmallerPickingRatioOnlyHelps, ()) {
  const Tagged t = *lu_parameters();
  LuParameters smaller = t.p;
  smaller.delta = t.p.delta * *rational_in(Rational(0), Rational(1));
  const LuConditions c = lu_t45_conditions(t.p), s = lu_t45_conditions(smaller);
  if (c.delta_rho0) RC_ASSERT(s.delta_rho0);
  if (c.delta_beta) RC_ASSERT(s.delta_beta);
  if (c.lemma43) RC_ASSERT(s.lemma43);
  if (c.lemma44) RC_ASSERT(s.lemma44);
}
