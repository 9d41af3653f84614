#pragma once
// The filtered evaluation of a predicate's sign (DESIGN.md § Numbers: static filter →
// interval → exact; "it must never answer a sign that the exact evaluation would not give").
//
// A kernel K is a polynomial with
//   static constexpr const char* name;
//   static constexpr std::size_t arity;
//   static constexpr std::array<int, arity> groups;        // magnitude group of each input
//   static constexpr std::array<const char*, arity> inputs; // names, for error messages
//   template <class T> static T eval(const std::array<T, arity>& x);
// evaluated in double (static filter, bound derived by ErrorModel), FilterInterval and
// Rational — the same code for all three.

#include "predicates/error_model.hpp"
#include "predicates/filter_interval.hpp"
#include "predicates/sign.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace anisocert::predicates {

// A NaN or an infinity given to a predicate: what() names the predicate and the input.
struct NonFiniteInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// How far the calls of this thread went (for benchmarks; never read by a predicate).
struct FilterStats {
  unsigned long long calls = 0, interval_stage = 0, exact_stage = 0;
};
FilterStats& filter_stats();

template <class K>
const ErrorModel& static_error_model() {
  static const ErrorModel model = [] {
    std::array<ErrorModel, K::arity> leaves;
    for (std::size_t i = 0; i < K::arity; ++i) leaves[i] = ErrorModel::leaf(K::groups[i]);
    return K::template eval<ErrorModel>(leaves);
  }();
  return model;
}

// Σ_k err_k Π_g max_g^{deg_kg} · (1 + 2⁻⁴⁰) + 2⁻⁶⁰⁰: the factor covers the rounding of this
// double computation itself (a few dozen operations, each <= 2⁻⁵³ relative), the constant
// every underflow error under the range guard (see error_model.hpp).
double static_error_bound(const ErrorModel& model, const std::array<double, magnitude_groups>& max);

// The range guard: each group's max is 0 or in [2⁻⁵⁰, 2⁵⁰].
bool in_static_range(const std::array<double, magnitude_groups>& max);

template <class K>
Sign exact_sign(const std::array<Rational, K::arity>& x) {
  return sign_of(K::template eval<Rational>(x));
}

template <class K>
Sign interval_then_exact(const std::array<FilterInterval, K::arity>& xi, const auto& exact_inputs) {
  if (auto s = K::template eval<FilterInterval>(xi).sign()) return *s;
  ++filter_stats().exact_stage;
  return exact_sign<K>(exact_inputs());
}

// The sign of K at double inputs, each taken as the rational it denotes.
template <class K>
Sign filtered_sign(const std::array<double, K::arity>& x) {
  ++filter_stats().calls;
  std::array<double, magnitude_groups> max{};
  for (std::size_t i = 0; i < K::arity; ++i) {
    if (!std::isfinite(x[i]))
      throw NonFiniteInput(std::string(K::name) + ": input " + K::inputs[i] + " = " + std::to_string(x[i]) +
                           " is not a finite number");
    max[K::groups[i]] = std::fmax(max[K::groups[i]], std::fabs(x[i]));
  }
  if (in_static_range(max)) {
    const double value = K::template eval<double>(x);
    const double bound = static_error_bound(static_error_model<K>(), max);
    if (value > bound) return Sign::positive;
    if (value < -bound) return Sign::negative;
  }
  ++filter_stats().interval_stage;
  std::array<FilterInterval, K::arity> xi;
  for (std::size_t i = 0; i < K::arity; ++i) xi[i] = FilterInterval(x[i]);
  return interval_then_exact<K>(xi, [&x] {
    std::array<Rational, K::arity> q;
    for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
    return q;
  });
}

// The sign of K at rational inputs: an interval enclosure first, exact when it cannot decide.
template <class K>
Sign filtered_sign(const std::array<Rational, K::arity>& q) {
  ++filter_stats().calls;
  ++filter_stats().interval_stage;
  std::array<FilterInterval, K::arity> xi;
  for (std::size_t i = 0; i < K::arity; ++i) xi[i] = FilterInterval::around(q[i]);
  return interval_then_exact<K>(xi, [&q] { return q; });
}

}  // namespace anisocert::predicates
