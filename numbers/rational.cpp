#include "numbers/rational.hpp"

#include "numbers/excerpt.hpp"

#include <cctype>
#include <cmath>

namespace anisocert {
namespace {

bool all_digits(std::string_view s) {
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Base-10 digits only: boost's string constructor would read a leading 0 as octal.
Integer decimal_integer(const std::string& digits) {
  Integer z;
  mpz_set_str(z.backend().data(), digits.c_str(), 10);
  return z;
}

// The text is quoted as an excerpt (numbers/excerpt.hpp): one short line, whatever it holds.
[[noreturn]] void reject(std::string_view text, const std::string& why) {
  throw NumberSyntaxError(quoted_excerpt(text) + " is not an exact number: " + why);
}

Integer parse_integer(std::string_view whole, std::string_view digits_with_sign) {
  std::string_view d = digits_with_sign;
  bool negative = false;
  if (!d.empty() && (d.front() == '+' || d.front() == '-')) {
    negative = d.front() == '-';
    d.remove_prefix(1);
  }
  if (d.empty() || !all_digits(d)) reject(whole, "expected an integer, got \"" + excerpt(digits_with_sign) + "\"");
  Integer z = decimal_integer(std::string(d));
  return negative ? Integer(-z) : z;
}

Integer power_of_ten(long e) {
  Integer p = 1;
  Integer base = 10;
  for (unsigned long k = static_cast<unsigned long>(e); k != 0; k >>= 1) {
    if (k & 1) p *= base;
    base *= base;
  }
  return p;
}

Rational parse_decimal(std::string_view text) {
  std::string_view s = text;
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  long exponent = 0;
  if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
    std::string_view exp_text = s.substr(e + 1);
    s = s.substr(0, e);
    std::string_view exp_digits = exp_text;
    if (!exp_digits.empty() && (exp_digits.front() == '+' || exp_digits.front() == '-')) exp_digits.remove_prefix(1);
    if (exp_digits.empty() || !all_digits(exp_digits)) reject(text, "malformed exponent");
    if (exp_digits.size() > 6) reject(text, "exponent too large");
    exponent = std::stol(std::string(exp_text));
  }
  std::string_view int_part = s, frac_part;
  if (auto dot = s.find('.'); dot != std::string_view::npos) {
    int_part = s.substr(0, dot);
    frac_part = s.substr(dot + 1);
  }
  if (int_part.empty() && frac_part.empty()) reject(text, "no digits");
  if (!all_digits(int_part) || !all_digits(frac_part)) reject(text, "unexpected character");
  exponent -= static_cast<long>(frac_part.size());
  if (exponent > max_decimal_exponent || exponent < -max_decimal_exponent)
    reject(text, "decimal exponent outside +-" + std::to_string(max_decimal_exponent));
  std::string digits = std::string(int_part) + std::string(frac_part);
  Integer mantissa = decimal_integer(digits.empty() ? std::string("0") : digits);
  if (negative) mantissa = -mantissa;
  if (exponent >= 0) return Rational(mantissa * power_of_ten(exponent));
  return Rational(mantissa, power_of_ten(-exponent));
}

}  // namespace

Rational parse_rational(std::string_view text) {
  if (text.empty()) reject(text, "empty");
  if (auto slash = text.find('/'); slash != std::string_view::npos) {
    Integer num = parse_integer(text, text.substr(0, slash));
    Integer den = parse_integer(text, text.substr(slash + 1));
    if (den == 0) reject(text, "zero denominator");
    return Rational(num, den);
  }
  return parse_decimal(text);
}

bool within_magnitude_limit(const Rational& q) {
  static const Rational largest = Rational(boost::multiprecision::pow(Integer(2), max_magnitude_bits));
  static const Rational smallest = 1 / largest;
  if (q == 0) return true;
  // Bit lengths first: they decide all but the values within a factor 4 of a bound.
  const long bits = static_cast<long>(mpz_sizeinbase(mpq_numref(q.backend().data()), 2)) -
                    static_cast<long>(mpz_sizeinbase(mpq_denref(q.backend().data()), 2));  // 2^(bits-1) < |q| < 2^(bits+1)
  if (bits < max_magnitude_bits && bits > -max_magnitude_bits) return true;
  if (bits > max_magnitude_bits + 1 || bits < -max_magnitude_bits - 1) return false;
  const Rational a = abs(q);
  return a >= smallest && a <= largest;
}

Rational parse_input_number(std::string_view text) {
  Rational q = parse_rational(text);
  if (!within_magnitude_limit(q))
    throw NumberSyntaxError(quoted_excerpt(text) + " is outside the magnitudes anisocert reads (0, or 2^-" +
                            std::to_string(max_magnitude_bits) + " to 2^" + std::to_string(max_magnitude_bits) +
                            " in absolute value)");
  return q;
}

Rational rational_from_double(double x) {
  if (std::isnan(x)) throw NumberSyntaxError("NaN is not an exact number");
  if (std::isinf(x)) throw NumberSyntaxError(std::string(x > 0 ? "+" : "-") + "infinity is not an exact number");
  return Rational(x);  // GMP's mpq_set_d: exact for finite doubles
}

std::string to_exact_string(const Rational& q) {
  Integer num = boost::multiprecision::numerator(q);
  Integer den = boost::multiprecision::denominator(q);
  // den = 2^a 5^b  <=>  q has a terminating decimal expansion with max(a, b) digits. The factors
  // are removed by GMP at once (mpz_scan1, mpz_remove): one division at a time was quadratic,
  // 5 s for 10^-100000.
  Integer rest = den;
  const unsigned long twos = mpz_scan1(rest.backend().data(), 0);
  mpz_tdiv_q_2exp(rest.backend().data(), rest.backend().data(), twos);
  Integer five = 5;
  const unsigned long fives = mpz_remove(rest.backend().data(), rest.backend().data(), five.backend().data());
  if (rest != 1) return num.str() + "/" + den.str();
  const unsigned long digits = std::max(twos, fives);
  Integer scaled = abs(num) * power_of_ten(digits) / den;  // exact: den divides 10^digits
  std::string s = scaled.str();
  if (digits > 0) {
    if (s.size() <= digits) s.insert(0, digits + 1 - s.size(), '0');
    s.insert(s.size() - digits, ".");
  }
  return (num < 0 ? "-" : "") + s;
}

}  // namespace anisocert
