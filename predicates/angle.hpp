#pragma once
// The angle θ = ∠abc measured by a metric M (LS Theorem 9, Corollary 10: "measured from the
// perspective of" a point), compared with a bound given by a rational cos or sin².
// With u = a − b, w = c − b: cos θ = uᵀMw / (|u|_M |w|_M).

#include "predicates/metric_dot.hpp"

#include <utility>

namespace anisocert::predicates {

// (uᵀMw, uᵀMu · wᵀMw) for u = a − b, w = c − b from the inputs a, b, c, M at x[0..8].
template <class T, std::size_t N>
constexpr std::pair<T, T> angle_dot_and_norms(const std::array<T, N>& x) {
  const T ux = x[0] - x[2], uy = x[1] - x[3], wx = x[4] - x[2], wy = x[5] - x[3];
  return {bilinear_form(x[6], x[7], x[8], ux, uy, wx, wy),
          T(quadratic_form(x[6], x[7], x[8], ux, uy) * quadratic_form(x[6], x[7], x[8], wx, wy))};
}

inline constexpr std::array<const char*, 10> angle_inputs{"a.x", "a.y", "b.x",   "b.y",   "c.x",
                                                           "c.y", "M.m11", "M.m12", "M.m22", "bound"};
inline constexpr std::array<int, 10> angle_groups{0, 0, 0, 0, 0, 0, 1, 1, 1, 2};

// The bound on θ: a cos k, or a sin² s².
enum class AngleBound { cos, sin2 };

// P = (uᵀMw)² − K · (uᵀMu)(wᵀMw), degree 4 / 2 / 2 (coordinates, metric, bound), with
//   K = k²      (AngleBound::cos):  sign(cos²θ − k²);
//   K = 1 − s²  (AngleBound::sin2): sign(cos²θ − (1 − s²)) = sign(s² − sin²θ).
template <AngleBound bound>
struct AngleKernel {
  static constexpr const char* name = bound == AngleBound::cos ? "angle against cos bound" : "angle against sin² bound";
  static constexpr std::size_t arity = 10;
  static constexpr auto groups = angle_groups;
  static constexpr auto inputs = angle_inputs;
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    const auto [dot, norms] = angle_dot_and_norms(x);
    if constexpr (bound == AngleBound::cos) {
      return dot * dot - x[9] * x[9] * norms;
    } else {
      return dot * dot - norms + x[9] * norms;
    }
  }
};
using AngleCosKernel = AngleKernel<AngleBound::cos>;
using AngleSinKernel = AngleKernel<AngleBound::sin2>;

// sign(cos θ − k) for a rational (or double) k in [−1, 1], θ = ∠abc measured by M, a ≠ b ≠ c.
// k >= 0: cos θ > k ⇔ uᵀMw > 0 and (uᵀMw)² > k²|u|²|w|²; k < 0 symmetrically.
template <class S>
Sign compare_angle_cos(const Point2<S>& a, const Point2<S>& b, const Point2<S>& c, const Sym2<S>& M, const S& k) {
  require_finite<S>("angle against cos bound", {{"k", k}});  // its sign is read before any kernel
  const Sign dot = metric_dot_sign(a, b, c, M);
  const Sign ks = k > 0 ? Sign::positive : k < 0 ? Sign::negative : Sign::zero;
  if (dot != ks) return static_cast<int>(dot) > static_cast<int>(ks) ? Sign::positive : Sign::negative;
  if (ks == Sign::zero) return Sign::zero;
  const Sign squares =
      filtered_sign<AngleCosKernel>(std::array<S, 10>{a.x, a.y, b.x, b.y, c.x, c.y, M.m11, M.m12, M.m22, k});
  return ks == Sign::positive ? squares : -squares;  // cos and k both negative: |cos| > |k| ⇔ cos < k
}

// θ >= arcsin(s) for s² = sin2 in [0, 1], i.e. θ >= 90° or sin²θ >= s² (LS Theorem 9's
// "θ >= arcsin χ"): sin²θ >= s² ⇔ cos²θ <= 1 − s².
template <class S>
bool angle_at_least_arcsin(const Point2<S>& a, const Point2<S>& b, const Point2<S>& c, const Sym2<S>& M,
                           const S& sin2) {
  require_finite<S>("angle against sin² bound", {{"sin2", sin2}});  // the obtuse case never reads it
  if (metric_dot_sign(a, b, c, M) != Sign::positive) return true;  // θ >= 90°
  return filtered_sign<AngleSinKernel>(std::array<S, 10>{a.x, a.y, b.x, b.y, c.x, c.y, M.m11, M.m12, M.m22, sin2}) !=
         Sign::positive;
}

}  // namespace anisocert::predicates
