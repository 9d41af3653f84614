// fields/normalized: LS §9's M′ = det(M)^(−1/2) M, against the closed form det(s M) = s² det M:
// every entry r·m of M′ must have r² det M = 1 up to the rounding the header states (det M exact
// here, in rationals), also for nearly singular M, where m11 m22 − m12² in doubles loses every digit.
#include "fields/normalized.hpp"
#include "numbers/rational.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace anisocert;
using predicates::Sym2;

namespace {

Rational exact_det(const Sym2<double>& M) {
  const Rational a = rational_from_double(M.m11), b = rational_from_double(M.m12), c = rational_from_double(M.m22);
  return a * c - b * b;
}

}  // namespace

TEST(FieldsNormalized, EveryEntryIsTheExactNormalizationWithinRounding) {
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> exponent(-6, 6), angle(0, 3.14159), ratio(0, 12);
  const Rational tolerance = rational_from_double(0x1p-48);  // header: a few ulps of s, half an ulp per entry
  int nearly_singular = 0;
  for (int n = 0; n < 4000; ++n) {
    const double l1 = std::pow(10.0, exponent(rng)), l2 = l1 * std::pow(10.0, -ratio(rng)), t = angle(rng);
    const double c = std::cos(t), s = std::sin(t);
    const Sym2<double> M{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c};
    const Rational det = exact_det(M);
    if (det <= 0 || M.m11 <= 0) continue;  // the doubles are not positive definite
    nearly_singular += l2 < l1 * 1e-9;
    const Sym2<double> N = fields::normalized(M);
    for (const auto& [m, n2] : {std::pair{M.m11, N.m11}, {M.m12, N.m12}, {M.m22, N.m22}}) {
      if (m == 0) {
        EXPECT_EQ(n2, 0.0);
        continue;
      }
      const Rational r = rational_from_double(n2) / rational_from_double(m);
      const Rational e = r * r * det - 1;
      ASSERT_LE(e < 0 ? -e : e, tolerance) << "M = [" << M.m11 << " " << M.m12 << "; " << M.m12 << " " << M.m22 << "]";
    }
  }
  EXPECT_GT(nearly_singular, 500);
}

TEST(FieldsNormalized, NotPositiveDefiniteIsReturnedUnchanged) {
  // Negative definite with det ≠ 1 (−I has det 1, so scaling it changes nothing: campaign mutant 186,
  // which dropped the m11 > 0 test, survived on it).
  for (const Sym2<double>& M : {Sym2<double>{1, 2, 1}, Sym2<double>{-1, 0, -1}, Sym2<double>{-1, 0, -4}, Sym2<double>{0, 0, 0}, Sym2<double>{1, 1, 1}}) {
    const Sym2<double> N = fields::normalized(M);
    EXPECT_TRUE(N.m11 == M.m11 && N.m12 == M.m12 && N.m22 == M.m22);
  }
}
