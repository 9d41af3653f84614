#pragma once
// The one exact rational type of the project and its exact text forms
// (DESIGN.md § Numbers and exactness: "Decimal strings and fractions are parsed exactly").

#include <boost/multiprecision/gmp.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace anisocert {

// Expression templates off: every operation yields a number, so generic code (the predicates'
// kernels, one template for double, intervals and rationals) deduces plain types.
using Rational = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;
using Integer = boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

// Thrown by parse_rational; what() names the offending text and what is wrong with it.
struct NumberSyntaxError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Parses, exactly, one of
//   integer   "-12", "+7"
//   decimal   "12.5", ".5", "3.", optionally with an exponent "1.25e-3", "4E2"
//   fraction  "-7/3" (integer numerator and a non-zero integer denominator)
// No surrounding blanks, no "inf"/"nan", no hexadecimal. Decimal exponents are limited to
// |e| <= max_decimal_exponent so that a hostile "1e999999999" cannot exhaust memory.
Rational parse_rational(std::string_view text);
inline constexpr long max_decimal_exponent = 100000;

// The magnitudes a number read from input (a file, a command line) may have: 0, or
// 2^-max_magnitude_bits <= |q| <= 2^max_magnitude_bits (about 7.4e-332 to 1.4e331), a little past
// the doubles' (2^-1074 to 2^1024). Beyond them (1e-100000 is a valid decimal) every predicate
// would fall to exact arithmetic on integers of hundreds of thousands of bits: such numbers are
// refused, not rounded. Decided exactly.
inline constexpr long max_magnitude_bits = 1100;
bool within_magnitude_limit(const Rational& q);

// parse_rational, then a NumberSyntaxError naming the text (an excerpt) when the value is beyond
// within_magnitude_limit: how every reader and every numeric option reads its numbers.
Rational parse_input_number(std::string_view text);

// The rational a binary double denotes, exactly (0.1 gives 3602879701896397/36028797018963968).
// Throws NumberSyntaxError for NaN and infinities, naming the value.
Rational rational_from_double(double x);

// The canonical exact text of q: a terminating decimal when the reduced denominator is
// 2^a 5^b ("12.5", "-3", "0.001"), otherwise the reduced fraction "p/q".
std::string to_exact_string(const Rational& q);

}  // namespace anisocert
