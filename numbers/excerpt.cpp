#include "numbers/excerpt.hpp"

#include <gmp.h>

namespace anisocert {

std::string excerpt(std::string_view text, std::size_t max_chars) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string s;
  std::size_t i = 0;
  for (; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const bool printable = c >= 0x20 && c < 0x7f;
    if (s.size() + (printable ? 1 : 4) > max_chars) break;
    if (printable) {
      s += static_cast<char>(c);
    } else {
      s += "\\x";
      s += hex[c >> 4];
      s += hex[c & 15];
    }
  }
  return i < text.size() ? s + "..." : s;
}

std::string quoted_excerpt(std::string_view text) { return "\"" + excerpt(text) + "\""; }

std::string exact_excerpt(const Rational& q) {
  std::string exact = to_exact_string(q);
  if (exact.size() <= excerpt_chars) return exact;
  // mpf's exponent range holds every magnitude a Rational may have (a double's would not: 1e-330
  // is 0 there); 64 bits give the ten digits.
  mpf_t f;
  mpf_init2(f, 64);
  mpf_set_q(f, q.backend().data());
  char buf[64];
  gmp_snprintf(buf, sizeof buf, "%.9Fe", f);
  mpf_clear(f);
  return std::string("≈") + buf;
}

}  // namespace anisocert
