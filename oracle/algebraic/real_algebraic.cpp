#include "oracle/algebraic/real_algebraic.hpp"

#include "numbers/filter_interval.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace anisocert::oracle {
namespace {

}  // namespace

std::vector<Polynomial> sturm_sequence(const Polynomial& p) {
  std::vector<Polynomial> s{p, p.derivative()};
  while (!s.back().is_zero()) {
    Polynomial r = divide(s[s.size() - 2], s.back()).second;
    s.push_back(Rational(-1) * r);
  }
  s.pop_back();
  return s;
}

namespace {

int sign_variations(const std::vector<Polynomial>& s, const Rational& x) {
  int v = 0;
  Sign last = Sign::zero;
  for (const Polynomial& q : s) {
    const Sign here = q.sign_at(x);
    if (here == Sign::zero) continue;
    if (last != Sign::zero && here != last) ++v;
    last = here;
  }
  return v;
}

// Number of distinct roots in (a, b].
int roots_in(const std::vector<Polynomial>& s, const Rational& a, const Rational& b) {
  return sign_variations(s, a) - sign_variations(s, b);
}

void isolate(const Polynomial& p, const std::vector<Polynomial>& s, Rational a, Rational b,
             std::vector<RealAlgebraic>& out) {
  const int n = roots_in(s, a, b);
  if (n == 0) return;
  if (n == 1) {
    if (p.sign_at(b) == Sign::zero) {
      out.emplace_back(p, b, b);
      return;
    }
    if (p.sign_at(a) != Sign::zero) {
      out.emplace_back(p, a, b);
      return;
    }
  }
  const Rational m = (a + b) / 2;
  isolate(p, s, a, m, out);
  isolate(p, s, m, b, out);
}

bool brackets_root(const Polynomial& g, const Rational& lo, const Rational& hi) {
  if (lo == hi) return g.sign_at(lo) == Sign::zero;
  const Sign a = g.sign_at(lo), b = g.sign_at(hi);
  return a == Sign::zero || b == Sign::zero || a != b;
}

Integer floor_of(const Rational& q) {
  Integer n = boost::multiprecision::numerator(q), d = boost::multiprecision::denominator(q);
  Integer f = n / d;  // truncates toward zero
  if (n < 0 && f * d != n) f -= 1;
  return f;
}

// 10^k as a rational, any integer k.
Rational ten_to(long k) {
  const Integer p = boost::multiprecision::pow(Integer{10}, static_cast<unsigned>(k < 0 ? -k : k));
  return k < 0 ? Rational(1) / Rational(p) : Rational(p);
}

// The decade e with 10^e <= |q| < 10^(e+1), q != 0: estimated from the digit counts of the
// numerator and the denominator (off by at most one), then corrected.
long decade(const Rational& q) {
  const Rational a = q < 0 ? Rational(-q) : q;
  long e = static_cast<long>(boost::multiprecision::numerator(a).str().size()) -
           static_cast<long>(boost::multiprecision::denominator(a).str().size());
  while (a >= ten_to(e + 1)) ++e;
  while (a < ten_to(e)) --e;
  return e;
}

// Round-half-even of a rational to an integer.
Integer round_even(const Rational& q) {
  const Integer f = floor_of(q);
  const Rational frac = q - Rational(f);
  if (frac > Rational(1, 2)) return f + 1;
  if (frac < Rational(1, 2)) return f;
  return f % 2 == 0 ? f : Integer(f + 1);
}

std::string format(const Integer& mantissa, long exponent) {
  // value = mantissa · 10^exponent
  const bool negative = mantissa < 0;
  std::string m = (negative ? Integer(-mantissa) : mantissa).str();
  const long point = static_cast<long>(m.size()) + exponent;  // digits before the decimal point
  std::string s;
  const long sci = point - 1;
  if (sci > 30 || sci < -30) {
    s = m.substr(0, 1) + (m.size() > 1 ? "." + m.substr(1) : "");
    if (s.find('.') != std::string::npos) {
      s.erase(s.find_last_not_of('0') + 1);
      if (s.back() == '.') s.pop_back();
    }
    s += "e" + std::to_string(sci);
  } else if (point <= 0) {
    s = "0." + std::string(static_cast<std::size_t>(-point), '0') + m;
  } else if (point >= static_cast<long>(m.size())) {
    s = m + std::string(static_cast<std::size_t>(point - static_cast<long>(m.size())), '0');
  } else {
    s = m.substr(0, static_cast<std::size_t>(point)) + "." + m.substr(static_cast<std::size_t>(point));
  }
  if (sci <= 30 && sci >= -30 && s.find('.') != std::string::npos) {
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
  }
  return (negative ? "-" : "") + s;
}

std::string decimal_of_rational(const Rational& q, int digits) {
  if (q == 0) return "0";
  const long e = decade(q);
  const Integer mant = round_even(q * ten_to(digits - 1 - e));
  return format(mant, e - (digits - 1));
}

}  // namespace

RealAlgebraic::RealAlgebraic(Polynomial squarefree, Rational lo, Rational hi)
    : p_(std::move(squarefree)), lo_(std::move(lo)), hi_(std::move(hi)) {
  if (p_.degree() < 1) throw std::invalid_argument("RealAlgebraic: constant polynomial");
  if (lo_ > hi_) throw std::invalid_argument("RealAlgebraic: lo > hi");
  if (lo_ == hi_ ? p_.sign_at(lo_) != Sign::zero
                 : (p_.sign_at(lo_) == Sign::zero || p_.sign_at(hi_) == Sign::zero ||
                    p_.sign_at(lo_) == p_.sign_at(hi_)))
    throw std::invalid_argument("RealAlgebraic: [lo, hi] does not bracket a root");
}

RealAlgebraic RealAlgebraic::rational(const Rational& q) {
  return RealAlgebraic(Polynomial(std::vector<Rational>{-q, 1}), q, q);
}

namespace {

// A dyadic rational in [mid − w/4, mid] for w = hi − lo: bisection points with short bit sizes.
Rational simple_midpoint(const Rational& lo, const Rational& hi) {
  const Rational w = hi - lo, mid = (lo + hi) / 2;
  const long k = static_cast<long>(boost::multiprecision::msb(boost::multiprecision::denominator(w))) -
                 static_cast<long>(boost::multiprecision::msb(boost::multiprecision::numerator(w))) + 3;
  if (k <= 0) {
    const Integer step = Integer(1) << static_cast<unsigned>(-k);
    const Integer f = boost::multiprecision::numerator(mid) / boost::multiprecision::denominator(mid);
    Integer m = f - (f % step);
    if (m > mid) m -= step;  // floor for negative values
    return Rational(m);
  }
  const Integer scale = Integer(1) << static_cast<unsigned>(k);
  const Rational scaled = mid * Rational(scale);
  Integer f = boost::multiprecision::numerator(scaled) / boost::multiprecision::denominator(scaled);
  if (Rational(f) > scaled) f -= 1;  // floor
  return Rational(f, scale);
}

}  // namespace

void RealAlgebraic::refine() const {
  if (is_exact()) return;
  const Rational m = simple_midpoint(lo_, hi_);
  const Sign sm = p_.sign_at(m);
  if (sm == Sign::zero) {
    lo_ = hi_ = m;
  } else if (sm == p_.sign_at(lo_)) {
    lo_ = m;
  } else {
    hi_ = m;
  }
}

namespace {

// The fraction of least denominator in [lo, hi] (the Stern–Brocot walk, by continued fractions).
Rational simplest_fraction(const Rational& lo, const Rational& hi) {
  if (lo <= 0 && hi >= 0) return 0;
  if (hi < 0) return -simplest_fraction(-hi, -lo);
  const Integer fl = floor_of(lo);
  if (Rational(fl) == lo) return lo;
  if (Rational(fl + 1) <= hi) return Rational(fl + 1);
  return Rational(fl) + 1 / simplest_fraction(1 / (hi - Rational(fl)), 1 / (lo - Rational(fl)));
}

}  // namespace

std::optional<Rational> RealAlgebraic::as_rational() const {
  if (is_exact()) return lo_;
  Integer common = 1;  // the lcm of the coefficients' denominators: P = common · p is integral
  for (const Rational& c : p_.coefficients()) common = boost::multiprecision::lcm(common, boost::multiprecision::denominator(c));
  const Rational lead = p_.leading() * Rational(common);
  const Integer lc = abs(boost::multiprecision::numerator(lead));
  // Two fractions of denominators ≤ |lc| differ by at least 1/lc², so below that width the
  // interval holds at most one of them, and it is the simplest one there.
  refine_below(Rational(1) / Rational(2 * lc * lc));
  if (is_exact()) return lo_;
  const Rational r = simplest_fraction(lo_, hi_);
  if (boost::multiprecision::denominator(r) <= lc && p_.sign_at(r) == Sign::zero) return r;
  return std::nullopt;
}

void RealAlgebraic::refine_below(const Rational& width) const {
  while (hi_ - lo_ > width) refine();
}

Sign RealAlgebraic::sign_of(const Polynomial& q) const {
  if (q.is_zero()) return Sign::zero;
  std::vector<anisocert::FilterInterval> coefficients;  // outward double enclosures, for a filter
  for (const Rational& c : q.coefficients()) coefficients.push_back(anisocert::FilterInterval::around(c));
  const auto decided = [&]() -> std::optional<Sign> {
    if (is_exact()) return q.sign_at(lo_);
    const anisocert::FilterInterval x{anisocert::FilterInterval::around(lo_).lo, anisocert::FilterInterval::around(hi_).hi};
    anisocert::FilterInterval v = coefficients.back();
    for (std::size_t i = coefficients.size() - 1; i-- > 0;) v = v * x + coefficients[i];
    if (const auto s = v.sign(); s && *s != Sign::zero) return *s;
    const auto [a, b] = q.range(lo_, hi_);
    if (a > 0) return Sign::positive;
    if (b < 0) return Sign::negative;
    return std::nullopt;
  };
  // Fast path: the interval value of q on a few refinements of [lo, hi].
  for (int k = 0; k < fast_refinements; ++k, refine())
    if (auto s = decided()) return *s;
  // Exact: q(α) = 0 ⇔ α is a root of g = gcd(q, p); g divides the square-free p, so [lo, hi]
  // holds at most one root of g, and holds α's exactly when g changes sign there.
  const Polynomial g = gcd(q, p_);
  if (g.degree() >= 1 && brackets_root(g, lo_, hi_)) return Sign::zero;
  // q(α) ≠ 0: refining must end with an interval value that excludes 0.
  while (true) {
    if (auto s = decided()) return *s;
    refine();
  }
}

std::string RealAlgebraic::decimal(int digits) const {
  if (digits < 1) throw std::invalid_argument("decimal: digits must be >= 1");
  if (sign_of(Polynomial::x()) == Sign::zero) return "0";
  while (true) {
    if (is_exact()) return decimal_of_rational(lo_, digits);
    if (lo_.sign() == hi_.sign() && lo_ != 0 && hi_ != 0 && decade(lo_) == decade(hi_)) {
      const long e = decade(lo_);
      const Rational scale = ten_to(digits - 1 - e);
      const Integer a = round_even(lo_ * scale), b = round_even(hi_ * scale);
      if (a == b) return format(a, e - (digits - 1));
      // A rounding tie inside the interval may be the value itself: test it exactly.
      const Rational tie = (Rational(floor_of(lo_ * scale)) + Rational(1, 2)) / scale;
      if (tie > lo_ && tie < hi_ && p_.sign_at(tie) == Sign::zero) return decimal_of_rational(tie, digits);
    } else if (lo_.sign() == hi_.sign() && lo_ != 0 && hi_ != 0) {
      // The decades differ: the value may be exactly the power of ten between them.
      const Rational boundary = ten_to(std::max(decade(lo_), decade(hi_))) * lo_.sign();
      if (boundary > lo_ && boundary < hi_ && p_.sign_at(boundary) == Sign::zero)
        return decimal_of_rational(boundary, digits);
    }
    refine();
  }
}

Sign compare(const RealAlgebraic& a, const RealAlgebraic& b) {
  if (a.is_exact() && b.is_exact()) return anisocert::sign_of(a.lo() - b.lo());
  // Equal ⇔ both are roots of g = gcd(p_a, p_b) and their intervals share that root.
  const Polynomial g = gcd(a.polynomial(), b.polynomial());
  if (g.degree() >= 1 && brackets_root(g, a.lo(), a.hi()) && brackets_root(g, b.lo(), b.hi())) {
    const Rational lo = a.lo() > b.lo() ? a.lo() : b.lo(), hi = a.hi() < b.hi() ? a.hi() : b.hi();
    if (lo <= hi && brackets_root(g, lo, hi)) return Sign::zero;
  }
  while (!(a.hi() < b.lo() || b.hi() < a.lo())) {
    a.refine();
    b.refine();
    if (a.is_exact() && b.is_exact()) return anisocert::sign_of(a.lo() - b.lo());
  }
  return a.hi() < b.lo() ? Sign::negative : Sign::positive;
}

std::vector<RealAlgebraic> real_roots(const Polynomial& p) {
  if (p.is_zero()) throw std::invalid_argument("real_roots of the zero polynomial");
  const Polynomial q = squarefree_part(p);
  std::vector<RealAlgebraic> roots;
  if (q.degree() < 1) return roots;
  // Cauchy's bound: every root has |x| < 1 + max |cᵢ/c_n|.
  Rational bound = 0;
  for (int i = 0; i < q.degree(); ++i) {
    const Rational r = abs(q.coefficient(i) / q.leading());
    bound = r > bound ? r : bound;
  }
  bound += 1;
  isolate(q, sturm_sequence(q), -bound, bound, roots);
  return roots;
}

int count_roots(const std::vector<Polynomial>& sturm, const Rational& a, const Rational& b) {
  return roots_in(sturm, a, b);
}

int multiplicity(const RealAlgebraic& alpha, const Polynomial& p) {
  int k = 0;
  for (Polynomial d = p; !d.is_zero() && alpha.sign_of(d) == Sign::zero; d = d.derivative()) ++k;
  return k;
}

}  // namespace anisocert::oracle
