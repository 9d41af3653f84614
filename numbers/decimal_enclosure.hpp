#pragma once
// Decimal text of a certified interval: lo rounded toward -inf, hi toward +inf, so that the
// decimal interval [lo, hi] still contains the exact value (it can only grow).

#include "numbers/interval.hpp"

#include <string>

namespace anisocert {

struct DecimalEnclosure {
  std::string lo;  // plain positional notation, e.g. "1.12783848", "-0.0031", "250"
  std::string hi;
};

// Each endpoint with `digits` significant decimal digits (digits >= 1), directed rounding.
DecimalEnclosure to_decimal(const Interval& x, int digits);

// The certified leading digits: the longest common prefix of lo and hi that is a correct
// truncation of every point of the interval, as text ("1.1278384855" for lo = 1.12783848556…1,
// hi = 1.12783848556…4). Meant for human-readable tables; the JSON carries lo and hi.
std::string certified_digits(const DecimalEnclosure& e);

// Significant decimal digits that lo and hi share: a guaranteed lower bound on the number of
// correct digits of either endpoint as an approximation of the exact value.
int common_significant_digits(const DecimalEnclosure& e);

}  // namespace anisocert
