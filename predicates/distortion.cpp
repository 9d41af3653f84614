#include "predicates/distortion.hpp"

#include "predicates/metric.hpp"
#include "predicates/sqrt_sign.hpp"

namespace anisocert::predicates {

TauSquared tau_squared(const Sym2<Rational>& P, const Sym2<Rational>& Q) {
  Metric2{P}, Metric2{Q};  // throws NotPositiveDefinite, naming the entry
  const Rational A = P.m11 * P.m22 - P.m12 * P.m12, C = Q.m11 * Q.m22 - Q.m12 * Q.m12;
  const Rational B = P.m11 * Q.m22 + P.m22 * Q.m11 - 2 * P.m12 * Q.m12;
  return {B, B * B - 4 * A * C, 2 * (A < C ? A : C)};
}

Sign compare_tau(const Sym2<Rational>& Mp, const Sym2<Rational>& Mq, const Sym2<Rational>& Ma,
                 const Sym2<Rational>& Mb) {
  // τ₁² − τ₂² = (B₁ + √D₁)/m₁ − (B₂ + √D₂)/m₂, same sign as m₂B₁ − m₁B₂ + m₂√D₁ − m₁√D₂; and
  // τ >= 0, so comparing squares compares τ.
  const TauSquared t1 = tau_squared(Mp, Mq), t2 = tau_squared(Ma, Mb);
  return sign_of_root_sum(t2.m * t1.B - t1.m * t2.B, t2.m, t1.D, -t1.m, t2.D);
}

Sign compare_tau_squared(const Sym2<Rational>& Mp, const Sym2<Rational>& Mq, const Rational& g) {
  const TauSquared t = tau_squared(Mp, Mq);
  return sign_of_root_sum(t.B - g * t.m, Rational(1), t.D);
}

}  // namespace anisocert::predicates
