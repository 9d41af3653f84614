#include "numbers/expansion.hpp"

#include "numbers/filter_interval.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace anisocert {

namespace {

bool even(double y) {
  std::uint64_t b;
  std::memcpy(&b, &y, sizeof b);
  return (b & 1) == 0;
}

}  // namespace

std::optional<double> rounded_quotient(const Expansion& X, const Expansion& D) {
  if (!X.exact() || !D.exact() || D.sign() == Sign::zero) return std::nullopt;
  if (X.sign() == Sign::zero) return 0.0;  // a vertex on an axis of symmetry, say
  // Rounding X/D is rounding |X|/|D|, with X/D's sign (ties to even are symmetric).
  const bool negative = X.sign() != D.sign();
  const Expansion x = X.sign() == Sign::negative ? -X : X, d = D.sign() == Sign::negative ? -D : D;
  double y = x.approx() / d.approx();
  for (int step = 0; step < 8; ++step) {
    // Normal doubles only, where the rounding is a 53-bit significand's (as Boost's conversion).
    if (!(y >= 0x1p-1021 && y <= 0x1p1022)) return std::nullopt;
    // r = x − y d, exactly: x/d against y. Then against the midpoint m = y ± h to the neighbour
    // on that side, h half their gap (a power of two, so h d is exact): x − m d = r ∓ h d.
    const Expansion r = x - d * Expansion(y);
    if (!r.exact()) return std::nullopt;
    if (r.sign() == Sign::zero) return negative ? -y : y;
    const bool above = r.sign() == Sign::positive;
    const double neighbour = above ? FilterInterval::next_up(y) : FilterInterval::next_down(y);
    const double h = std::fabs(neighbour - y) / 2;
    const Expansion t = above ? r - d * Expansion(h) : r + d * Expansion(h);
    if (!t.exact()) return std::nullopt;
    if (t.sign() == Sign::zero) {  // a tie: the even one of y and its neighbour
      const double even_one = even(y) ? y : neighbour;
      return negative ? -even_one : even_one;
    }
    if ((t.sign() == Sign::negative) == above) return negative ? -y : y;  // x/d within half a gap of y
    y = neighbour;
  }
  return std::nullopt;
}

Rational exact_value(const Expansion& e) {
  Rational q = 0;
  for (double c : e.components()) q += Rational(c);
  return q;
}

}  // namespace anisocert
