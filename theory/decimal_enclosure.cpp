#include "theory/decimal_enclosure.hpp"

#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace anisocert::theory {
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

std::string certified_digits(const DecimalEnclosure& e) {
  // A common prefix of two positional decimals of the same sign and integer-part length is a
  // truncation of every number between them.
  size_t k = 0;
  while (k < e.lo.size() && k < e.hi.size() && e.lo[k] == e.hi[k]) ++k;
  std::string p = e.lo.substr(0, k);
  bool same_integer_part = e.lo.find('.') == e.hi.find('.') || e.lo == e.hi;
  if (!same_integer_part || p.empty() || p == "-") return "?";
  if (k == e.lo.size() && k == e.hi.size()) return p;  // exact
  if (p.back() == '.') p.pop_back();
  if (p.find('.') == std::string::npos && p.size() < e.lo.substr(0, e.lo.find('.')).size()) return "?";
  return p + "…";
}

int common_significant_digits(const DecimalEnclosure& e) {
  int count = 0;
  bool started = false;
  for (size_t k = 0; k < e.lo.size() && k < e.hi.size() && e.lo[k] == e.hi[k]; ++k) {
    char c = e.lo[k];
    if (c == '-' || c == '.') continue;
    if (c != '0') started = true;
    if (started) ++count;
  }
  return count;
}

}  // namespace anisocert::theory
