#pragma once
// A double that knows whether it is exact: the double evaluation of a polynomial, each operation
// checked for rounding by an error-free transformation (Shewchuk 1997, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", §2):
//   a ± b = s exactly when s is finite and two_sum's error term (Theorem 7) is 0;
//   a · b = p exactly when p is finite and fma(a, b, −p) = 0 with |p| >= 2^−968 (below that the
//     error term may underflow: expansion.hpp), or when p = 0 and a or b is 0.
// When no operation rounded, the double value is the polynomial's value at the inputs, exactly,
// and so is its sign. This is the predicates' stage between the static filter and the
// expansions (predicates/filtered_sign.hpp): a grid's right angles and cocircular quadruples,
// whose double evaluation is 0 and rounds nowhere, are decided at the cost of a few double
// operations each instead of expansions'. It changes no answer: an evaluation it calls exact is
// the exact value (`ExactDouble.*` in tests/numbers_exact_double_test.cpp against rationals).
//
// The same evaluation order as double's: a kernel's eval<ExactDouble> computes, operation for
// operation, the double value eval<double> computes, since the build forbids contracting a·b + c
// into an fma (-ffp-contract=off, CMakeLists.txt; GCC's default for C++ allows it wherever the
// target has an fma instruction).

#include "numbers/sign.hpp"

#include <cmath>

namespace anisocert {

class ExactDouble {
 public:
  ExactDouble() = default;  // 0, exactly
  ExactDouble(double x) : value_(x), exact_(std::isfinite(x)) {}  // NOLINT: a double is an exact value

  double value() const { return value_; }
  // The value's sign: the exact sign when exact().
  Sign sign() const { return value_ > 0 ? Sign::positive : value_ < 0 ? Sign::negative : Sign::zero; }
  // False once an operation rounded, overflowed or underflowed (or an input was not finite).
  bool exact() const { return exact_; }

  friend ExactDouble operator+(const ExactDouble& a, const ExactDouble& b) {
    return {a.value_ + b.value_, a.exact_ && b.exact_, a.value_, b.value_};
  }
  friend ExactDouble operator-(const ExactDouble& a, const ExactDouble& b) {
    return {a.value_ - b.value_, a.exact_ && b.exact_, a.value_, -b.value_};
  }
  friend ExactDouble operator-(const ExactDouble& a) { return {-a.value_, a.exact_}; }
  friend ExactDouble operator*(const ExactDouble& a, const ExactDouble& b) {
    const double p = a.value_ * b.value_;
    if (!(a.exact_ && b.exact_)) return {p, false};
    if (p == 0) return {p, a.value_ == 0 || b.value_ == 0};
    return {p, std::isfinite(p) && std::fabs(p) >= 0x1p-968 && std::fma(a.value_, b.value_, -p) == 0};
  }

 private:
  ExactDouble(double v, bool exact) : value_(v), exact_(exact) {}
  // s = a + b rounded: exact when s is finite and two_sum's error term is 0 (it is the exact error
  // when s is finite; a NaN term, from s − a overflowing, counts as inexact).
  ExactDouble(double s, bool exact, double a, double b) : value_(s), exact_(exact && std::isfinite(s)) {
    if (!exact_) return;
    const double bv = s - a, av = s - bv;
    exact_ = (a - av) + (b - bv) == 0;
  }

  double value_ = 0;
  bool exact_ = true;
};

}  // namespace anisocert
