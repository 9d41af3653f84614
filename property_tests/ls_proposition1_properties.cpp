// LS Proposition 1 and BWY Definition 2.1 (relative distortion), exactly: τ >= 1, symmetry,
// submultiplicativity, the two distance inequalities, and two independent computations of
// "τ <= γ" (PSD of γ²M_p − M_q, and the quadratic-irrational τ²), plus a third from F.

#include "predicates/distortion.hpp"
#include "predicates/length_compare.hpp"
#include "property_tests/generators/metrics.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::Sign;
using namespace anisocert::gen;

namespace {
const mpfr_prec_t prec = 200;
}  // namespace

RC_GTEST_PROP(LS_P1, TauIsAtLeastOneSymmetricAndExactlyOneForEqualMetrics, ()) {
  const auto [p, q] = *metric_pair();
  RC_TAG(p.kind + "/" + q.kind);
  RC_ASSERT(compare_tau_squared(p.M, q.M, Rational(1)) != Sign::negative);
  RC_ASSERT(compare_tau(p.M, q.M, q.M, p.M) == Sign::zero);
  if (p.kind == "equal") {
    RC_ASSERT(compare_tau_squared(p.M, q.M, Rational(1)) == Sign::zero);
    RC_ASSERT(tau_at_most(p.M, q.M, Rational(1)));
  } else if (!(p.M.m11 == q.M.m11 && p.M.m12 == q.M.m12 && p.M.m22 == q.M.m22)) {
    // τ <= 1 ⇔ M_p − M_q ⪰ 0 and M_q − M_p ⪰ 0 ⇔ M_p = M_q: distinct metrics have τ > 1.
    RC_ASSERT(compare_tau_squared(p.M, q.M, Rational(1)) == Sign::positive);
  }
}

// The PSD test (tau_at_most) and the root of the quadratic (compare_tau_squared) must agree
// for every γ², in particular just above and just below τ².
RC_GTEST_PROP(LS_P1, TwoComputationsOfTauAgree, ()) {
  const auto [p, q] = *metric_pair();
  RC_TAG(p.kind);
  const anisocert::Interval t2 = tau_squared_enclosure(p.M, q.M, prec);
  for (const Rational& g : std::vector<Rational>{rational_above(t2), rational_below(t2), Rational(1), *rational_in(Rational(1), Rational(3))})
    RC_ASSERT(tau_at_most(p.M, q.M, g) == (compare_tau_squared(p.M, q.M, g) != Sign::positive));
  RC_ASSERT(tau_at_most(p.M, q.M, rational_above(t2)));
}

// d_p(a,b)/τ <= d_q(a,b) <= τ d_p(a,b): with γ² >= τ², γ² d_p² − d_q² >= 0 and γ² d_q² − d_p² >= 0.
RC_GTEST_PROP(LS_P1, DistancesAreDistortedByAtMostTau, ()) {
  const auto [p, q] = *metric_pair();
  const auto a = *point(), b = *point();
  RC_TAG(p.kind);
  const Rational g = tau2_above(p.M, q.M);
  RC_ASSERT(compare_scaled_lengths(g, a, b, p.M, a, b, q.M) != Sign::negative);
  RC_ASSERT(compare_scaled_lengths(g, a, b, q.M, a, b, p.M) != Sign::negative);
}

RC_GTEST_PROP(LS_P1, TauIsSubmultiplicative, ()) {
  const auto [p, a] = *metric_pair();
  const Tagged q = *metric();
  RC_TAG(p.kind);
  // τ(p, q) <= τ(p, a) τ(a, q) <= γ₁γ₂ for rational γ₁² >= τ(p, a)², γ₂² >= τ(a, q)².
  RC_ASSERT(tau_at_most(p.M, q.M, Rational(tau2_above(p.M, a.M) * tau2_above(a.M, q.M))));
}

// compare_tau (sums of square roots, exact) agrees with the certified enclosures of τ² wherever
// those are disjoint, and says τ(p, q) > τ(p, p) = 1 for distinct metrics.
RC_GTEST_PROP(LS_P1, TauComparisonAgreesWithEnclosures, ()) {
  const auto [p, q] = *metric_pair();
  const auto [a, b] = *metric_pair();
  RC_TAG(p.kind + "/" + a.kind);
  const Sign s = compare_tau(p.M, q.M, a.M, b.M);
  const anisocert::Interval t1 = tau_squared_enclosure(p.M, q.M, prec), t2 = tau_squared_enclosure(a.M, b.M, prec);
  if (certainly_less(t1, t2)) RC_ASSERT(s == Sign::negative);
  if (certainly_less(t2, t1)) RC_ASSERT(s == Sign::positive);
  if (s == Sign::zero) RC_ASSERT(!certainly_less(t1, t2) && !certainly_less(t2, t1));
  RC_ASSERT(compare_tau(p.M, q.M, p.M, p.M) == (p.kind == "equal" ? Sign::zero : compare_tau_squared(p.M, q.M, Rational(1))));
}

// BWY Definition 2.1: γ(p, q) = max(‖F_q F_p⁻¹‖₂, ‖F_p F_q⁻¹‖₂), so γ(p, q) <= γ ⇔ γ² I − AᵀA ⪰ 0
// for A = F_q F_p⁻¹ and for A = F_p F_q⁻¹: computed from the frames F, not from the metrics.
RC_GTEST_PROP(BWY_D21, DistortionFromFramesAgreesWithMetrics, ()) {
  const auto [p, q] = *metric_pair();
  RC_TAG(p.kind);
  auto spectral_at_most = [](const Frame& X, const Frame& Y, const Rational& g) {
    // A = X Y⁻¹; AᵀA = Y⁻ᵀ (XᵀX) Y⁻¹, computed column by column.
    const Point2<Rational> c1 = X.apply(Y.inverse({1, 0})), c2 = X.apply(Y.inverse({0, 1}));
    const Sym2<Rational> AtA{c1.x * c1.x + c1.y * c1.y, c1.x * c2.x + c1.y * c2.y, c2.x * c2.x + c2.y * c2.y};
    return scaled_difference_psd(g, Sym2<Rational>{1, 0, 1}, AtA);
  };
  const anisocert::Interval t2 = tau_squared_enclosure(p.M, q.M, prec);
  for (const Rational& g : std::vector<Rational>{rational_above(t2), rational_below(t2), *rational_in(Rational(1), Rational(4))})
    RC_ASSERT(tau_at_most(p.M, q.M, g) == (spectral_at_most(q.F, p.F, g) && spectral_at_most(p.F, q.F, g)));
}
