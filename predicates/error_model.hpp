#pragma once
// Derivation of the static filters' error bounds (the method of Meyer & Pion's FPG, done by
// the compiler on the very code of each predicate).
//
// A predicate's polynomial P is evaluated once, at start-up, in this number type instead of
// double. Every input is a leaf of a magnitude group g (coordinates, metric entries, scalar
// bounds), standing for any double x with |x| <= max_g. A value is a list of monomials
// Π max_g^{deg_g}, each with two coefficients: `mag`, a bound on the magnitude, and `err`, a
// bound on the rounding error of its part of the double evaluation, both in units of the
// monomial. Rules (u = 2⁻⁵³, fl(x ∘ y) = (x ∘ y)(1 + δ), |δ| <= u, barring underflow):
//   a ± b : mag = ma + mb,            err = ea + eb + u (ma + ea + mb + eb)
//   a · b : mag = ma mb,              err = ea mb + ma eb + ea eb + u (ma + ea)(mb + eb)
// merged per multidegree. Then |fl(P) − P| <= Σ_k err_k Π_g max_g^{deg_kg}. Underflow is
// handled by the caller (filtered_sign.hpp), which only uses the bound when every group max is
// 0 or within [2⁻⁵⁰, 2⁵⁰] and adds an absolute 2⁻⁶⁰⁰ that dominates every underflow error.

#include <array>
#include <vector>

namespace anisocert::predicates {

inline constexpr int magnitude_groups = 3;
using Multidegree = std::array<int, magnitude_groups>;

class ErrorModel {
 public:
  struct Monomial {
    Multidegree degree;
    double mag, err;
  };

  ErrorModel(double constant = 0);  // NOLINT: an exact constant (as the literals in P)
  static ErrorModel leaf(int group);

  const std::vector<Monomial>& monomials() const { return terms_; }

  friend ErrorModel operator+(const ErrorModel& a, const ErrorModel& b);
  friend ErrorModel operator-(const ErrorModel& a, const ErrorModel& b);
  friend ErrorModel operator-(const ErrorModel& a);
  friend ErrorModel operator*(const ErrorModel& a, const ErrorModel& b);

 private:
  void add(const Monomial& m);
  std::vector<Monomial> terms_;
};

}  // namespace anisocert::predicates
