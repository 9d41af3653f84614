#pragma once
// Working precision of theory/ and the default number of printed digits.

#include <mpfr.h>

namespace anisocert::theory {

// Significant decimal digits printed for each endpoint unless asked otherwise.
inline constexpr int default_digits = 40;

// Bits of working precision for `digits` printed digits: log2(10) < 3.33 bits per digit plus
// 64 guard bits for the error growth of the short formula chains of theory/ (each a few dozen
// MPFI operations); never below 256 bits (77 digits).
inline mpfr_prec_t working_precision(int digits) {
  mpfr_prec_t bits = static_cast<mpfr_prec_t>(digits) * 10 / 3 + 64;
  return bits < 256 ? 256 : bits;
}

}  // namespace anisocert::theory
