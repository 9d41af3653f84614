#pragma once
// Exact signs of sums of square roots with rational coefficients, for comparisons of
// quadratic irrationals (τ², LS Proposition 1; the LS Lemma 8 and Lemma 22 comparisons).

#include "numbers/sign.hpp"

namespace anisocert::predicates {

// sign(x + y·√X), X >= 0.
Sign sign_of_root_sum(const Rational& x, const Rational& y, const Rational& X);

// sign(x + y·√X + z·√Y), X, Y >= 0.
Sign sign_of_root_sum(const Rational& x, const Rational& y, const Rational& X, const Rational& z, const Rational& Y);

}  // namespace anisocert::predicates
