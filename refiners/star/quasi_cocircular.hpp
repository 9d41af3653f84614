#pragma once
// γ₀-cocircularity, LU Definition 3.6 in 2D: four points a, b, c, d are γ₀-cocircular for a metric
// M when two metrics N, N′ with γ(M, N), γ(M, N′), γ(N, N′) ≤ γ₀ disagree on whether d lies
// inside the circumellipse of a, b, c (LU Lemma 3.7).
//
// Decided here over the sub-family {N : γ(M, N) ≤ √γ₀}, in which γ(N, N′) ≤ γ₀ holds by the
// triangle inequality γ(N, N′) ≤ γ(N, M) γ(M, N′): a `true` is a true γ₀-cocircularity, a `false`
// may miss one whose witnesses lie outside that family. The in-circle determinant is linear in
// the metric, f(N) = ⟨C, N⟩ with C = Σᵢ cofactorᵢ uᵢuᵢᵀ (uᵢ = the points minus d); writing
// N = M^½ T M^½, γ(M, N) ≤ √γ₀ means T's eigenvalues lie in [1/γ₀, γ₀], and the extremes of
// ⟨M^½ C M^½, T⟩ over those T come from the eigenvalues λ of M C: Σ λ·(γ₀ or 1/γ₀).
// Floating point: the refiners' Pick_valid uses it to choose among points that are all valid.
#include "predicates/point.hpp"

namespace anisocert::refiners::star {

bool quasi_cocircular(const predicates::Point2<double>& a, const predicates::Point2<double>& b,
                      const predicates::Point2<double>& c, const predicates::Point2<double>& d,
                      const predicates::Sym2<double>& M, double gamma0);

}  // namespace anisocert::refiners::star
