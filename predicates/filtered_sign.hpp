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
// evaluated in double (static filter, bound derived by ErrorModel), FilterInterval, and exactly
// in Expansion (double inputs) or Rational — the same code for all.

#include "predicates/error_model.hpp"
#include "numbers/exact_double.hpp"
#include "numbers/expansion.hpp"
#include "numbers/filter_interval.hpp"
#include "numbers/sign.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace anisocert::predicates {

// A NaN or an infinity given to a predicate: what() names the predicate and the input.
struct NonFiniteInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// How many calls of this thread went past the static stage (for benchmarks; never read by a
// predicate).
struct FilterStats {
  unsigned long long interval_stage = 0, exact_stage = 0;
};
inline thread_local FilterStats filter_stats_of_thread;
inline FilterStats& filter_stats() { return filter_stats_of_thread; }

// The static bound of kernel K, Σ_k err_k Π_g max_g^{deg_kg}, from ErrorModel at compile time;
// each err_k is multiplied by (1 + 2⁻⁴⁰), which covers the rounding of the compile-time
// evaluation and of evaluating this sum in double (a few dozen operations, each <= 2⁻⁵³
// relative); 2⁻⁶⁰⁰ is added for every underflow error under the range guard (error_model.hpp).
template <class K>
inline constexpr ErrorModel static_error_model = [] {
  std::array<ErrorModel, K::arity> leaves{};
  for (std::size_t i = 0; i < K::arity; ++i) leaves[i] = ErrorModel::leaf(K::groups[i]);
  return K::template eval<ErrorModel>(leaves);
}();

// Translation: a kernel may declare `origin`, for each input the index of the input it is
// measured from (−1: none; an input's own index: it becomes 0), when its polynomial depends on
// the coordinates only through those differences (orientation, in-circle). The static stage then
// runs on the rounded differences, with a bound over their magnitudes rather than the
// coordinates': points 10⁻⁴ apart near (0.5, 0.5) cost (0.5/10⁻⁴)⁴ less bound in an in-circle.
template <class K>
concept Translatable = requires { K::origin; };

template <class K>
  requires Translatable<K>
inline constexpr ErrorModel translated_error_model = [] {
  for (std::size_t i = 0; i < K::arity; ++i) {
    const int o = K::origin[i];
    // An origin is its own origin, and lies in the group of the inputs measured from it.
    if (o >= 0 && (K::origin[o] != o || K::groups[o] != K::groups[i])) throw "Translatable: malformed origin";
  }
  std::array<ErrorModel, K::arity> leaves{};
  for (std::size_t i = 0; i < K::arity; ++i) {
    const int o = K::origin[i];
    leaves[i] = o >= 0 && o != static_cast<int>(i) ? ErrorModel::rounded_leaf(K::groups[i]) : ErrorModel::leaf(K::groups[i]);
  }
  return K::template eval<ErrorModel>(leaves);
}();

template <int n>
[[gnu::always_inline]] inline double power_of(double x) {
  if constexpr (n == 0) {
    return 1;
  } else {
    return x * power_of<n - 1>(x);
  }
}

template <const ErrorModel& model, int k = 0>
[[gnu::always_inline]] inline double error_bound(const std::array<double, magnitude_groups>& max) {
  if constexpr (k == 0) {
    return 0x1p-600 + error_bound<model, 1>(max);
  } else if constexpr (k > model.size()) {
    return 0;
  } else {
    constexpr ErrorModel::Monomial t = model[k - 1];
    static_assert(t.degree[0] + t.degree[1] + t.degree[2] <= 8,
                  "the range guard's underflow and overflow argument assumes total degree <= 8");
    constexpr double err = t.err * (1 + 0x1p-40);
    const double term = err * power_of<t.degree[0]>(max[0]) * power_of<t.degree[1]>(max[1]) *
                        power_of<t.degree[2]>(max[2]);
    return term + error_bound<model, k + 1>(max);
  }
}

template <class K>
constexpr bool uses_group(int g) {
  for (int x : K::groups)
    if (x == g) return true;
  return false;
}

// The range guard: the max of each group the kernel uses is 0 or in [2⁻⁵⁰, 2⁵⁰].
template <class K>
[[gnu::always_inline]] inline bool in_static_range(const std::array<double, magnitude_groups>& max) {
  bool ok = true;
  [&]<int... g>(std::integer_sequence<int, g...>) {
    ((ok &= !uses_group<K>(g) || (max[g] <= 0x1p50 && (max[g] >= 0x1p-50 || max[g] == 0))), ...);
  }(std::make_integer_sequence<int, magnitude_groups>{});
  return ok;
}

[[noreturn]] void throw_non_finite(const char* predicate, const char* input, double value);

// For predicates that combine several kernels and may decide before every input reached a
// kernel: rejects a NaN or an infinity among double inputs up front (no-op for rationals).
template <class S>
void require_finite(const char* predicate, std::initializer_list<std::pair<const char*, S>> inputs) {
  if constexpr (std::is_same_v<S, double>)
    for (const auto& [name, value] : inputs)
      if (!std::isfinite(value)) throw_non_finite(predicate, name, value);
}

template <class K>
Sign exact_sign(const std::array<Rational, K::arity>& x) {
  return sign_of(K::template eval<Rational>(x));
}

// The exact sign at double inputs: in expansions (numbers/expansion.hpp), without GMP's
// allocations and gcds; in rationals only when an expansion overflowed or underflowed.
template <class K>
Sign exact_sign_of_doubles(const std::array<double, K::arity>& x) {
  std::array<Expansion, K::arity> e;
  for (std::size_t i = 0; i < K::arity; ++i) e[i] = Expansion(x[i]);
  const Expansion value = K::template eval<Expansion>(e);
  if (value.exact()) return value.sign();
  std::array<Rational, K::arity> q;
  for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
  return exact_sign<K>(q);
}

template <class K>
Sign interval_then_exact(const std::array<FilterInterval, K::arity>& xi, const auto& exact_inputs) {
  if (auto s = K::template eval<FilterInterval>(xi).sign()) return *s;
  ++filter_stats().exact_stage;
  return exact_sign<K>(exact_inputs());
}

// The max of |x_i| per magnitude group, unrolled at compile time (the group of each input is a
// constant, so every max stays in a register). A NaN input is skipped by the max but makes the
// double value NaN, which fails both comparisons below; an infinite one fails the range guard.
// Either way the call leaves the static stage, and the slow path rejects it.
// Indices of the inputs of group g, in order.
template <class K, int g>
constexpr auto group_indices() {
  constexpr std::size_t n = [] {
    std::size_t c = 0;
    for (int x : K::groups) c += x == g;
    return c;
  }();
  std::array<std::size_t, n> idx{};
  std::size_t c = 0;
  for (std::size_t i = 0; i < K::arity; ++i)
    if (K::groups[i] == g) idx[c++] = i;
  return idx;
}

// max |x_i| over idx[lo, hi), as a balanced tree (independent maxima run in parallel).
template <auto idx, std::size_t lo, std::size_t hi, std::size_t N>
[[gnu::always_inline]] inline double tree_max(const std::array<double, N>& x) {
  if constexpr (hi - lo == 0) {
    return 0;
  } else if constexpr (hi - lo == 1) {
    return std::fabs(x[idx[lo]]);
  } else {
    constexpr std::size_t mid = lo + (hi - lo) / 2;
    return std::max(tree_max<idx, lo, mid>(x), tree_max<idx, mid, hi>(x));
  }
}

template <class K>
[[gnu::always_inline]] inline std::array<double, magnitude_groups> group_maxima(const std::array<double, K::arity>& x) {
  constexpr auto i0 = group_indices<K, 0>();
  constexpr auto i1 = group_indices<K, 1>();
  constexpr auto i2 = group_indices<K, 2>();
  return {tree_max<i0, 0, i0.size()>(x), tree_max<i1, 0, i1.size()>(x), tree_max<i2, 0, i2.size()>(x)};
}

// A static stage: K evaluated in doubles against the bound that `model` gives for the inputs'
// group maxima; nothing when that bound does not decide, or a group leaves the static range
// (which a NaN or an infinity does too, or it makes the value NaN).
template <class K, const ErrorModel& model>
[[gnu::always_inline]] inline std::optional<Sign> static_sign(const std::array<double, K::arity>& x) {
  const std::array<double, magnitude_groups> max = group_maxima<K>(x);
  if (in_static_range<K>(max)) [[likely]] {
    const double value = K::template eval<double>(x);
    const double bound = error_bound<model>(max);
    if (value > bound) return Sign::positive;
    if (value < -bound) return Sign::negative;
  }
  return std::nullopt;
}

// An enclosure of K's value at double inputs from the static stage: the double evaluation ± the
// static bound (widened by an ulp for the rounding of those two sums), as cheap as that
// evaluation; nothing outside the stage's range. For measured values, where a sign is not enough.
// A Translatable kernel is evaluated on the rounded differences, with their model's bound (see
// below), so that the enclosure's width scales with the element, not with its distance from 0.
// `value` is K::eval<double>(x), computed by the caller when several kernels are parts of one
// computation on the same inputs (Cramer's determinants: one elimination, four enclosures).
template <class K, const ErrorModel& model>
std::optional<FilterInterval> static_enclosure_of_value(const std::array<double, K::arity>& x, double value) {
  const std::array<double, magnitude_groups> max = group_maxima<K>(x);
  if (!in_static_range<K>(max) || !std::isfinite(value)) return std::nullopt;
  const double bound = error_bound<model>(max);
  return FilterInterval::widen(value - bound, value + bound);
}

template <class K, const ErrorModel& model>
std::optional<FilterInterval> static_enclosure_with(const std::array<double, K::arity>& x) {
  return static_enclosure_of_value<K, model>(x, K::template eval<double>(x));
}

// A translatable kernel's inputs as the rounded differences from their origins.
template <class K>
  requires Translatable<K>
std::array<double, K::arity> translated(const std::array<double, K::arity>& x) {
  std::array<double, K::arity> t;
  for (std::size_t i = 0; i < K::arity; ++i) t[i] = K::origin[i] < 0 ? x[i] : x[i] - x[K::origin[i]];
  return t;
}

// The translated static stage (see Translatable), on the rounded differences: tried only when
// the plain one fails, so that the common case does not pay for the differences.
template <class K>
std::optional<Sign> translated_static_sign(const std::array<double, K::arity>& x) {
  if constexpr (Translatable<K>) return static_sign<K, translated_error_model<K>>(translated<K>(x));
  return std::nullopt;
}

template <class K>
std::optional<FilterInterval> static_enclosure(const std::array<double, K::arity>& x) {
  if constexpr (Translatable<K>) {
    return static_enclosure_with<K, translated_error_model<K>>(translated<K>(x));
  } else {
    return static_enclosure_with<K, static_error_model<K>>(x);
  }
}

// The translated, interval and exact stages, out of line: rare, and large.
template <class K>
[[gnu::noinline]] Sign filtered_sign_slow(const std::array<double, K::arity>& x) {
  if (const auto s = translated_static_sign<K>(x)) return *s;
  for (std::size_t i = 0; i < K::arity; ++i)
    if (!std::isfinite(x[i])) throw_non_finite(K::name, K::inputs[i], x[i]);
  // The double evaluation, each operation checked for rounding (numbers/exact_double.hpp): when
  // none rounded, its sign is the exact sign. That is how most calls that get here end: a right
  // angle, four cocircular points of a grid, whose value is 0 exactly and rounds nowhere.
  std::array<ExactDouble, K::arity> xd;
  for (std::size_t i = 0; i < K::arity; ++i) xd[i] = x[i];
  const ExactDouble value = K::template eval<ExactDouble>(xd);
  if (value.exact()) return value.sign();
  // The interval stage, unless the double evaluation is 0: round-to-nearest is monotone, so that
  // value lies in the interval evaluation (each end rounded to nearest, then widened; no
  // contraction into fma: -ffp-contract=off, CMakeLists.txt), which then holds 0 and does not decide.
  // Either way the exact stage gives the answer: this only chooses the faster path.
  if (value.value() != 0) {
    ++filter_stats().interval_stage;
    std::array<FilterInterval, K::arity> xi;
    for (std::size_t i = 0; i < K::arity; ++i) xi[i] = FilterInterval(x[i]);
    if (auto s = K::template eval<FilterInterval>(xi).sign()) return *s;
  }
  ++filter_stats().exact_stage;
  return exact_sign_of_doubles<K>(x);
}

// The sign of K at double inputs, each taken as the rational it denotes. Throws
// NonFiniteInput for a NaN or an infinity.
template <class K>
[[gnu::always_inline]] inline Sign filtered_sign(const std::array<double, K::arity>& x) {
  if (const auto s = static_sign<K, static_error_model<K>>(x)) [[likely]] return *s;
  return filtered_sign_slow<K>(x);
}

// The sign of a kernel K whose total degree is beyond the static stage's range guard (at most 8;
// K then has no `origin`, so no translated static stage either): at double inputs the later
// stages (the double evaluation checked for rounding, intervals, expansions), at rational inputs
// intervals, then rationals.
template <class K, class S>
Sign high_degree_sign(const std::array<S, K::arity>& x) {
  if constexpr (std::is_same_v<S, double>) {
    return filtered_sign_slow<K>(x);
  } else {
    std::array<FilterInterval, K::arity> xi;
    for (std::size_t i = 0; i < K::arity; ++i) xi[i] = FilterInterval::around(x[i]);
    return interval_then_exact<K>(xi, [&] { return x; });
  }
}

// The sign of K at rational inputs: an interval enclosure first, exact when it cannot decide.
template <class K>
Sign filtered_sign(const std::array<Rational, K::arity>& q) {
  ++filter_stats().interval_stage;
  std::array<FilterInterval, K::arity> xi;
  for (std::size_t i = 0; i < K::arity; ++i) xi[i] = FilterInterval::around(q[i]);
  return interval_then_exact<K>(xi, [&q] { return q; });
}

}  // namespace anisocert::predicates
