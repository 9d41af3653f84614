#include "numbers/expansion.hpp"

#include "numbers/filter_interval.hpp"

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
  const bool negative = X.sign() != D.sign() && X.sign() != Sign::zero;
  const Expansion x = X.sign() == Sign::negative ? -X : X, d = D.sign() == Sign::negative ? -D : D;
  // The sign of m − x/d for m = (y + z)/2, exactly: of (y + z) d − 2x (d > 0); nothing when
  // inexact.
  const auto against_midpoint = [&](double y, double z) -> std::optional<Sign> {
    const Expansion e = (Expansion(y) + Expansion(z)) * d - (x + x);
    if (!e.exact()) return std::nullopt;
    return e.sign();
  };
  double y = x.approx() / d.approx();
  for (int step = 0; step < 8; ++step) {
    // Normal doubles only, where the rounding is a 53-bit significand's (as Boost's conversion).
    if (!(y >= 0x1p-1021 && y <= 0x1p1022)) return std::nullopt;
    const double up = FilterInterval::next_up(y), down = FilterInterval::next_down(y);
    const auto above = against_midpoint(y, up), below = against_midpoint(down, y);
    if (!above || !below) return std::nullopt;
    if (*above == Sign::negative) {  // x/d beyond the midpoint to up
      y = up;
    } else if (*below == Sign::positive) {  // x/d below the midpoint to down
      y = down;
    } else {
      if (*above == Sign::zero && !even(y)) y = up;  // a tie: the even neighbour
      if (*below == Sign::zero && !even(y)) y = down;
      return negative ? -y : y;
    }
  }
  return std::nullopt;
}

Rational exact_value(const Expansion& e) {
  Rational q = 0;
  for (double c : e.components()) q += Rational(c);
  return q;
}

}  // namespace anisocert
