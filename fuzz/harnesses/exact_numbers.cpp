// Exact numbers (docs/fuzzing.md § Parsers): parse_rational on any text.
//   - a text it refuses gets a NumberSyntaxError of one short line;
//   - a number it reads comes back from its canonical text (to_exact_string) unchanged, and that
//     text is a fixed point;
//   - a decimal it reads has, as its nearest double, glibc's correctly rounded strtod of the same
//     text (an independent reading: the rational lies no farther from strtod's double than from
//     either neighbouring double).
// Limit: 256 bytes (a number in a mesh file is a few dozen characters; exponents are bounded by
// max_decimal_exponent, so the longest work is one 10^100000).
#include "fuzz/support/finding.hpp"
#include "fuzz/support/message_contract.hpp"
#include "numbers/rational.hpp"

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

using anisocert::Rational;
using anisocert::fuzz::require;

namespace {

constexpr std::size_t max_input = 256;

// |q − d| ≤ |q − d'| for both doubles d' next to d.
bool nearest_double(const Rational& q, double d) {
  const Rational dq = anisocert::rational_from_double(d);
  const Rational gap = abs(q - dq);
  for (double towards : {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}) {
    const double n = std::nextafter(d, towards);
    if (std::isfinite(n) && abs(q - anisocert::rational_from_double(n)) < gap) return false;
  }
  return true;
}

bool plain_decimal(const std::string& t) {
  if (t.empty() || t.find_first_not_of("+-0123456789.eE") != std::string::npos) return false;
  return t.find_first_of("0123456789") != std::string::npos;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > max_input) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Rational q;
  try {
    q = anisocert::parse_rational(text);
  } catch (const anisocert::NumberSyntaxError& e) {
    anisocert::fuzz::require_one_short_line(e.what(), "");
    return 0;
  }
  const std::string canonical = anisocert::to_exact_string(q);
  require(anisocert::parse_rational(canonical) == q, "\"" + canonical + "\" does not read back as the number it shows");
  require(anisocert::to_exact_string(anisocert::parse_rational(canonical)) == canonical,
          "the canonical text \"" + canonical + "\" is not a fixed point");
  if (plain_decimal(text)) {
    std::setlocale(LC_NUMERIC, "C");
    char* end = nullptr;
    const double d = std::strtod(text.c_str(), &end);
    if (end == text.c_str() + text.size() && std::isfinite(d) && d != 0 && std::fabs(d) >= 0x1p-1022)
      require(nearest_double(q, d), "strtod(\"" + text.substr(0, 60) + "\") is not the double nearest the number read");
  }
  return 0;
}
