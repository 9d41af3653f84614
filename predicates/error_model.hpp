#pragma once
// Derivation of the static filters' error bounds (the method of Meyer & Pion's FPG, done by
// the compiler, at compile time, on the very code of each predicate).
//
// A predicate's polynomial P is evaluated in this number type instead of double. Every input
// is a leaf of a magnitude group g (coordinates, metric entries, scalar bounds), standing for
// any double x with |x| <= max_g. A value is a list of monomials Π max_g^{deg_g}, each with two
// coefficients: `mag`, a bound on the magnitude, and `err`, a bound on the rounding error of
// its part of the double evaluation, both in units of the monomial. Rules (u = 2⁻⁵³,
// fl(x ∘ y) = (x ∘ y)(1 + δ), |δ| <= u, barring underflow):
//   a ± b : mag = ma + mb,            err = ea + eb + u (ma + ea + mb + eb)
//   a · b : mag = ma mb,              err = ea mb + ma eb + ea eb + u (ma + ea)(mb + eb)
// merged per multidegree. Then |fl(P) − P| <= Σ_k err_k Π_g max_g^{deg_kg}. Underflow is
// handled by the caller (filtered_sign.hpp), which only uses the bound when every group max is
// 0 or within [2⁻⁵⁰, 2⁵⁰] and adds an absolute 2⁻⁶⁰⁰ that dominates every underflow error.
// (The compile-time evaluation itself rounds to nearest; the caller's factor 1 + 2⁻⁴⁰ covers it.)

#include <array>

namespace anisocert::predicates {

inline constexpr int magnitude_groups = 3;
using Multidegree = std::array<int, magnitude_groups>;

class ErrorModel {
 public:
  static constexpr int max_terms = 12;
  static constexpr double u = 0x1p-53;
  struct Monomial {
    Multidegree degree{};
    double mag = 0, err = 0;
  };

  constexpr ErrorModel() = default;
  constexpr ErrorModel(double constant) {  // NOLINT: an exact constant (as the literals in P)
    if (constant != 0) terms_[count_++] = {Multidegree{}, constant < 0 ? -constant : constant, 0.0};
  }
  static constexpr ErrorModel leaf(int group) {
    ErrorModel e;
    e.terms_[0].degree[group] = 1;
    e.terms_[0].mag = 1;
    e.count_ = 1;
    return e;
  }
  // A leaf given as the rounded difference c = fl(x − o) of two doubles, standing for the exact
  // x − o: |c| <= max_g, so |x − o| <= max_g/(1 − u) and |c − (x − o)| <= u |x − o|; 1 + 2u and
  // 2u bound both. (A difference that underflows is exact, by Hauser's theorem.)
  static constexpr ErrorModel rounded_leaf(int group) {
    ErrorModel e = leaf(group);
    e.terms_[0].mag = 1 + 2 * u;
    e.terms_[0].err = 2 * u;
    return e;
  }

  constexpr int size() const { return count_; }
  constexpr const Monomial& operator[](int k) const { return terms_[k]; }

  friend constexpr ErrorModel operator+(const ErrorModel& a, const ErrorModel& b) {
    ErrorModel r;
    for (int k = 0; k < a.count_; ++k) r.add(a.terms_[k]);
    for (int k = 0; k < b.count_; ++k) r.add(b.terms_[k]);
    // The sum's own rounding: u times a bound on its computed magnitude, spread per monomial.
    for (int k = 0; k < r.count_; ++k) r.terms_[k].err += u * (r.terms_[k].mag + r.terms_[k].err);
    return r;
  }
  friend constexpr ErrorModel operator-(const ErrorModel& a, const ErrorModel& b) { return a + b; }
  friend constexpr ErrorModel operator-(const ErrorModel& a) { return a; }  // magnitudes are unsigned
  friend constexpr ErrorModel operator*(const ErrorModel& a, const ErrorModel& b) {
    ErrorModel r;
    for (int i = 0; i < a.count_; ++i)
      for (int j = 0; j < b.count_; ++j) {
        const Monomial &x = a.terms_[i], &y = b.terms_[j];
        Monomial m;
        for (int g = 0; g < magnitude_groups; ++g) m.degree[g] = x.degree[g] + y.degree[g];
        m.mag = x.mag * y.mag;
        m.err = x.err * y.mag + x.mag * y.err + x.err * y.err + u * (x.mag + x.err) * (y.mag + y.err);
        r.add(m);
      }
    return r;
  }

 private:
  constexpr void add(const Monomial& m) {
    for (int k = 0; k < count_; ++k)
      if (terms_[k].degree == m.degree) {
        terms_[k].mag += m.mag;
        terms_[k].err += m.err;
        return;
      }
    if (count_ == max_terms) throw "ErrorModel: too many monomials";  // a compile-time error
    terms_[count_++] = m;
  }
  std::array<Monomial, max_terms> terms_{};
  int count_ = 0;
};

}  // namespace anisocert::predicates
