#include "theory/sign_change_root.hpp"

#include <stdexcept>

namespace anisocert::theory {
namespace {

struct Mpfr {
  explicit Mpfr(mpfr_prec_t prec) { mpfr_init2(v, prec); }
  ~Mpfr() { mpfr_clear(v); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
  mpfr_t v;
};

Interval at(const std::function<Interval(const Interval&)>& f, mpfr_srcptr x, mpfr_prec_t prec) {
  return f(Interval(x, x, prec));
}

}  // namespace

bool brackets_sign_change(const std::function<Interval(const Interval&)>& f, const Rational& lo,
                          const Rational& hi, mpfr_prec_t prec) {
  return lo < hi && f(Interval(lo, prec)).certainly_negative() && f(Interval(hi, prec)).certainly_positive();
}

Interval enclose_sign_change(const std::function<Interval(const Interval&)>& f, const Rational& a,
                             const Rational& b, mpfr_prec_t prec) {
  Mpfr lo(prec), hi(prec), mid(prec);
  if (mpfr_set_q(lo.v, a.backend().data(), MPFR_RNDN) != 0 || mpfr_set_q(hi.v, b.backend().data(), MPFR_RNDN) != 0)
    throw std::logic_error("enclose_sign_change: bracket ends must be exact prec-bit numbers");
  if (!(a < b) || !at(f, lo.v, prec).certainly_negative() || !at(f, hi.v, prec).certainly_positive())
    throw std::logic_error("enclose_sign_change: no certified sign change on the given bracket");
  // Invariant: f(lo) certainly < 0 < f(hi). Each step halves hi - lo, so adjacency is reached
  // within prec + (exponent of b - a) steps; the bound below is generous and finite.
  for (long step = 0; step < 4 * static_cast<long>(prec) + 64; ++step) {
    mpfr_add(mid.v, lo.v, hi.v, MPFR_RNDN);
    mpfr_div_2ui(mid.v, mid.v, 1, MPFR_RNDN);
    if (mpfr_cmp(mid.v, lo.v) <= 0 || mpfr_cmp(mid.v, hi.v) >= 0) break;  // lo, hi adjacent
    Interval value = at(f, mid.v, prec);
    if (value.certainly_negative())
      mpfr_set(lo.v, mid.v, MPFR_RNDN);
    else if (value.certainly_positive())
      mpfr_set(hi.v, mid.v, MPFR_RNDN);
    else
      break;  // f's own width cannot decide here: [lo, hi] is as tight as f allows
  }
  return Interval(lo.v, hi.v, prec);
}

}  // namespace anisocert::theory
