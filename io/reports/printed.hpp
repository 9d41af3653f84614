#pragma once
// How reports print an approximate number next to an exact verdict.
#include "numbers/rational.hpp"

#include <cmath>
#include <sstream>
#include <string>

namespace anisocert::io {

// ostream's default, 6 significant digits ("5", "1.2", "0.707107").
inline std::string as_printed(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

// k of n as a percentage, printed as as_printed does ("74.2793%"); "0%" of nothing.
inline std::string percent(std::size_t k, std::size_t n) {
  return n == 0 ? "0%" : as_printed(100.0 * static_cast<double>(k) / static_cast<double>(n)) + "%";
}

// x rounded outward (down, or up) to 10 significant decimal digits, exactly: the ends of an
// enclosure stay ends of an enclosure in print.
inline std::string outward(double x, bool up) {
  if (x == 0 || !std::isfinite(x)) return as_printed(x);
  const int e = static_cast<int>(std::floor(std::log10(std::fabs(x))));
  Rational scale = 1;
  for (int k = 0; k < std::abs(9 - e); ++k) scale *= 10;
  if (9 - e < 0) scale = 1 / scale;
  const Rational q = rational_from_double(x) * scale;
  Integer n = boost::multiprecision::numerator(q) / boost::multiprecision::denominator(q);  // towards zero
  if (Rational(n) != q && (q > 0) == up) n += up ? 1 : -1;
  return to_exact_string(Rational(n) / scale);
}

}  // namespace anisocert::io
