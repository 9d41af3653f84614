#include "property_tests/generators/rationals.hpp"

#include "numbers/decimal_enclosure.hpp"
#include "theory/ls_theorem11.hpp"

namespace anisocert::gen {

Rational ten_to_minus(int k) { return Rational(1, boost::multiprecision::pow(Integer{10}, k)); }

rc::Gen<Rational> rational_in(const Rational& lo, const Rational& hi) {
  rc::Gen<long> denominator = rc::gen::oneOf(rc::gen::map(rc::gen::inRange(1, 9), [](int d) {
                                               long n = 1;
                                               while (d-- > 0) n *= 10;
                                               return n;
                                             }),
                                             rc::gen::inRange<long>(2, 1000000));
  return rc::gen::mapcat(denominator, [lo, hi](long n) {
    return rc::gen::map(rc::gen::inRange<long>(1, n), [lo, hi, n](long k) { return Rational(lo + (hi - lo) * Rational(k, n)); });
  });
}

Rational theta_max_truncated(int decimals) {
  static const Rational theta_max_lo =
      parse_rational(anisocert::to_decimal(theory::ls_t11_theta_max_deg(600), 150).lo);
  const Integer scale = boost::multiprecision::pow(Integer{10}, decimals);
  const Rational scaled = theta_max_lo * scale;
  const Integer truncated = boost::multiprecision::numerator(scaled) / boost::multiprecision::denominator(scaled);
  return Rational(truncated, scale);
}

rc::Gen<Theta> admissible_theta() {
  const Rational below_max = theta_max_truncated(6);
  return rc::gen::weightedOneOf<Theta>({
      {1, rc::gen::just(Theta{Rational(0), "zero"})},
      {3, rc::gen::map(rc::gen::inRange(0, 21), [](int d) { return Theta{Rational(d), "integer"}; })},
      {6, rc::gen::map(rational_in(Rational(0), below_max), [](Rational q) { return Theta{q, "decimal_or_fraction"}; })},
      {4, rc::gen::map(rc::gen::inRange(1, 71), [](int k) { return Theta{theta_max_truncated(k), "near_max"}; })},
  });
}

std::ostream& operator<<(std::ostream& os, const Theta& t) { return os << to_exact_string(t.value) << " (" << t.kind << ")"; }

}  // namespace anisocert::gen
