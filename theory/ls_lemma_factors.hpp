#pragma once
// The distance factors of LS §10 (Labelle & Shewchuk 2003), as certified intervals of γ.

#include "numbers/interval.hpp"

namespace anisocert::theory {

// LS Lemma 5: d_v(q) = d_w(q) >= d_w(v) / sqrt(γ² − 1). Requires γ > 1 (certainly).
Interval ls_lemma5_factor(const Interval& gamma);
// LS Lemmas 14–15: no distance shorter than bdr_min(γ) / (γ³ + γ).
Interval ls_lemma14_factor(const Interval& gamma);
// LS Lemmas 18–19: d_w(q) > γ² sqrt(γ² + 1) ℓ (also Lemma 18's β).
Interval ls_lemma18_factor(const Interval& gamma);
// LS Lemma 21 (and Lemma 22): γ sqrt(γ² + 1) m.
Interval ls_lemma21_site_factor(const Interval& gamma);
// LS Lemma 21: bdr_min(γ) / (γ⁴ + γ²).
Interval ls_lemma21_bdr_factor(const Interval& gamma);
// LS Lemma 23 and Theorem 11: bdr_min(γ) / ((γ⁵ + γ³) sqrt(γ² + 1)).
Interval ls_lemma23_factor(const Interval& gamma);

}  // namespace anisocert::theory
