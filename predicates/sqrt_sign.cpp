#include "predicates/sqrt_sign.hpp"

#include <stdexcept>

namespace anisocert::predicates {

Sign sign_of_root_sum(const Rational& x, const Rational& y, const Rational& X) {
  if (X < 0) throw std::domain_error("sign_of_root_sum: negative radicand");
  const Sign sx = sign_of(x), sy = X == 0 ? Sign::zero : sign_of(y);
  if (sy == Sign::zero) return sx;
  if (sx == Sign::zero || sx == sy) return sy;
  // Opposite signs: the larger magnitude wins; |x| vs |y|√X ⇔ x² vs y²X.
  const Sign cmp = sign_of(x * x - y * y * X);
  return cmp == Sign::zero ? Sign::zero : cmp == Sign::positive ? sx : sy;
}

Sign sign_of_root_sum(const Rational& x, const Rational& y, const Rational& X, const Rational& z, const Rational& Y) {
  if (Y < 0) throw std::domain_error("sign_of_root_sum: negative radicand");
  // a = x + y√X, b = z√Y.
  const Sign sa = sign_of_root_sum(x, y, X), sb = Y == 0 ? Sign::zero : sign_of(z);
  if (sb == Sign::zero) return sa;
  if (sa == Sign::zero || sa == sb) return sb;
  // Opposite signs: compare a² = x² + y²X + 2xy√X with b² = z²Y.
  const Sign cmp = sign_of_root_sum(x * x + y * y * X - z * z * Y, 2 * x * y, X);
  return cmp == Sign::zero ? Sign::zero : cmp == Sign::positive ? sa : sb;
}

}  // namespace anisocert::predicates
