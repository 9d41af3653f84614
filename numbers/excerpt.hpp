#pragma once
// How a message quotes the input it refuses (DESIGN.md § Command line: one line naming what is
// wrong): a short, single-line excerpt. Printable ASCII is kept, every other byte (a newline, a
// control character, a byte of UTF-8) is shown as \xNN, and at most `max_chars` characters are
// shown, then "...". A message never carries a file's bytes raw: a newline in a number would forge
// a second line of output, a megabyte token a megabyte message.
#include "numbers/rational.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace anisocert {

inline constexpr std::size_t excerpt_chars = 40;

std::string excerpt(std::string_view text, std::size_t max_chars = excerpt_chars);

// The excerpt between double quotes, as messages quote a token: found "\x01\x02z".
std::string quoted_excerpt(std::string_view text);

// How a message names a value read from a file: its exact text (to_exact_string) when that has at
// most excerpt_chars characters, else "≈" and ten significant digits ("≈1.000000000e-330"): a
// decimal may have a hundred thousand digits, and the first forty of 0.000…01 say nothing.
std::string exact_excerpt(const Rational& q);

}  // namespace anisocert
