#pragma once
// Boissonnat, Wormser & Yvinec, "Anisotropic diagrams: Labelle Shewchuk approach revisited",
// §4: the overlap condition of Lemma 2 and the minimal-interdistance conditions of §4.2.

#include "numbers/interval.hpp"

#include <optional>

namespace anisocert::theory {

// BWY Lemma 2's left-hand side (γ² − 1)(1 + γ)²(1 + 4γ)² B⁴, for exact rationals and for
// intervals alike.
template <class T>
T bwy_lemma2_lhs(const T& gamma, const T& B) {
  T g1 = gamma + 1, g4 = 4 * gamma + 1, B2 = B * B;
  return T(gamma * gamma - 1) * g1 * g1 * g4 * g4 * B2 * B2;
}

// The largest γ >= 1 with bwy_lemma2_lhs(γ, B) <= 1, for B > 1: the lhs is strictly
// increasing in γ on [1, ∞) (a product of non-negative increasing factors, the first zero at
// γ = 1), −1 at γ = 1 after subtracting 1 and positive at γ = 2, so the root is unique.
Interval bwy_lemma2_gamma_max(const Rational& B, mpfr_prec_t prec);

// The check a reader can repeat on printed rationals lo <= hi, exactly: the condition holds at
// lo and its lhs is >= 1 at hi, so γ_max ∈ [lo, hi] (the lhs is increasing for γ >= 1).
bool bwy_lemma2_gamma_max_bracket_verified(const Rational& B, const Rational& lo, const Rational& hi);

// The certified decision for given rationals B > 1, G >= 1 (each exact).
struct BwyConditions {
  bool lemma2;            // (G² − 1)(1 + G)²(1 + 4G)² B⁴ <= 1          (Lemma 2, §4.2)
  bool violator_factor;   // G² sqrt(G⁴ − 1) <= 1                        (§4.2)
  bool shape_factor;      // G² sqrt(G² + 1) <= B                         (§4.2)
  bool angle_bound;       // (G² − 1) B² < 1: B becomes an angle bound via LS Corollary 10
  bool positive_interdistance() const { return lemma2 && violator_factor && shape_factor; }
  bool all() const { return positive_interdistance() && angle_bound; }
};
BwyConditions bwy_s42_conditions(const Rational& B, const Rational& G);

// The factors of §4.2's bound d^w_min >= min(d_min / (G² sqrt(G⁴ − 1)), B d_min / (G² sqrt(G² + 1)),
// bdr_min(G) / ((G⁵ + G³) sqrt(G² + 1)), lfs_min / G).
struct BwyInterdistanceFactors {
  std::optional<Interval> violator;  // 1 / (G² sqrt(G⁴ − 1)); none (unbounded) when G = 1
  Interval shape;                    // B / (G² sqrt(G² + 1))
  Interval bdr;                      // 1 / ((G⁵ + G³) sqrt(G² + 1)), as LS Lemma 23
  Interval lfs;                      // 1 / G
};
BwyInterdistanceFactors bwy_s42_factors(const Rational& B, const Rational& G, mpfr_prec_t prec);

}  // namespace anisocert::theory
