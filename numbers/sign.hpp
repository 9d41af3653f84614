#pragma once
// The answer of every predicate, and of every interval that decides one: a sign.

#include "numbers/rational.hpp"

namespace anisocert {

enum class Sign { negative = -1, zero = 0, positive = 1 };

inline Sign sign_of(const Rational& q) { return q < 0 ? Sign::negative : q > 0 ? Sign::positive : Sign::zero; }
inline Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
inline Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }

}  // namespace anisocert
