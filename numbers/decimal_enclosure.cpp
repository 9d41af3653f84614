#include "numbers/decimal_enclosure.hpp"

#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>

namespace anisocert {
namespace {

std::string positional(mpfr_srcptr x, int digits, mpfr_rnd_t rnd) {
  if (mpfr_zero_p(x)) return "0";
  if (!mpfr_number_p(x)) throw std::domain_error("decimal text of a non-finite endpoint");
  mpfr_exp_t exp = 0;
  std::unique_ptr<char, void (*)(char*)> raw(mpfr_get_str(nullptr, &exp, 10, static_cast<size_t>(digits), x, rnd),
                                            mpfr_free_str);
  std::string mant(raw.get());
  std::string sign;
  if (mant.front() == '-') {
    sign = "-";
    mant.erase(0, 1);
  }
  // value = 0.mant * 10^exp
  std::string out;
  const long n = static_cast<long>(mant.size());
  if (exp <= 0) {
    out = "0." + std::string(static_cast<size_t>(-exp), '0') + mant;
  } else if (exp >= n) {
    out = mant + std::string(static_cast<size_t>(exp - n), '0');
  } else {
    out = mant.substr(0, static_cast<size_t>(exp)) + "." + mant.substr(static_cast<size_t>(exp));
  }
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  return sign + out;
}

}  // namespace

DecimalEnclosure to_decimal(const Interval& x, int digits) {
  if (digits < 1) throw std::invalid_argument("to_decimal: digits must be >= 1");
  return {positional(x.lower(), digits, MPFR_RNDD), positional(x.upper(), digits, MPFR_RNDU)};
}

namespace {

// Length of the integer part (with its sign) of a positional decimal.
std::size_t integer_part_length(const std::string& s) {
  const std::size_t dot = s.find('.');
  return dot == std::string::npos ? s.size() : dot;
}

// Length of the common prefix of lo and hi when both have the same sign and integer-part
// length (so that a common prefix is a truncation of every number between them), else none.
std::optional<std::size_t> comparable_prefix(const DecimalEnclosure& e) {
  if (integer_part_length(e.lo) != integer_part_length(e.hi) || (e.lo[0] == '-') != (e.hi[0] == '-'))
    return std::nullopt;
  std::size_t k = 0;
  while (k < e.lo.size() && k < e.hi.size() && e.lo[k] == e.hi[k]) ++k;
  return k;
}

}  // namespace

std::string certified_digits(const DecimalEnclosure& e) {
  if (e.lo == e.hi) return e.lo;  // exact
  const std::optional<std::size_t> k = comparable_prefix(e);
  // The prefix must cover the whole integer part, or the magnitude would be lost.
  if (!k || *k < integer_part_length(e.lo)) return "?";
  std::string p = e.lo.substr(0, *k);
  if (p.back() == '.') p.pop_back();
  return p + "…";
}

int common_significant_digits(const DecimalEnclosure& e) {
  const std::optional<std::size_t> k = comparable_prefix(e);
  if (!k) return 0;
  int count = 0;
  bool started = false;
  for (std::size_t i = 0; i < *k; ++i) {
    const char c = e.lo[i];
    if (c == '-' || c == '.') continue;
    if (c != '0') started = true;
    if (started) ++count;
  }
  return count;
}

}  // namespace anisocert
