#pragma once
// Comparison of two squared metric lengths, one scaled by a scalar s:
//   P = s · (b − a)ᵀ M₁ (b − a) − (d − c)ᵀ M₂ (d − c)
// degree 2 in the coordinates, 1 in the metrics, 1 in s. Positive: s·d₁(a, b)² > d₂(c, d)².
// Serves the radius-edge ratio (LS Theorem 9: β >= r/ℓ; BWY §4: β(v) = r(v)/δ(t_v) <= B) and
// the distance inequalities of LS Lemmas 5, 16, 22 and Proposition 1.

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

namespace anisocert::predicates {

struct ScaledLengthCompareKernel {
  static constexpr const char* name = "scaled length comparison";
  static constexpr std::size_t arity = 15;
  static constexpr std::array<int, arity> groups{2, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1};
  static constexpr std::array<const char*, arity> inputs{"s",      "a.x",    "a.y",    "b.x", "b.y",
                                                         "M1.m11", "M1.m12", "M1.m22", "c.x", "c.y",
                                                         "d.x",    "d.y",    "M2.m11", "M2.m12", "M2.m22"};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return x[0] * quadratic_form(x[5], x[6], x[7], T(x[3] - x[1]), T(x[4] - x[2])) -
           quadratic_form(x[12], x[13], x[14], T(x[10] - x[8]), T(x[11] - x[9]));
  }
};

// sign(s · d_{M1}(a, b)² − d_{M2}(c, d)²)
template <class S>
Sign compare_scaled_lengths(const S& s, const Point2<S>& a, const Point2<S>& b, const Sym2<S>& M1,
                            const Point2<S>& c, const Point2<S>& d, const Sym2<S>& M2) {
  return filtered_sign<ScaledLengthCompareKernel>(std::array<S, 15>{
      s, a.x, a.y, b.x, b.y, M1.m11, M1.m12, M1.m22, c.x, c.y, d.x, d.y, M2.m11, M2.m12, M2.m22});
}

// Radius-edge ratio r/ℓ <= B for a Voronoi vertex q of the sites v₀, v₁, v₂ (LS Theorem 9,
// BWY §4): r = d_{v₀}(q), ℓ = min over pairs of d(vᵢ, vⱼ) = min(d_{vᵢ}(vⱼ), d_{vⱼ}(vᵢ)); so
// r/ℓ <= B ⇔ B²·d_{vᵢ}(vⱼ)² >= r² for all six ordered pairs. B2 = B². q must be the vertex
// (d_{vᵢ}(q) equal for the three sites); r is measured from v₀.
template <class S>
bool radius_edge_at_most(const S& B2, const Point2<S>& q, const std::array<Point2<S>, 3>& v,
                         const std::array<Sym2<S>, 3>& M) {
  require_finite<S>("radius-edge ratio", {{"B2", B2}, {"q.x", q.x}, {"q.y", q.y}});
  for (int i = 0; i < 3; ++i)
    require_finite<S>("radius-edge ratio", {{"v.x", v[i].x}, {"v.y", v[i].y}, {"M.m11", M[i].m11}, {"M.m12", M[i].m12},
                                         {"M.m22", M[i].m22}});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j && compare_scaled_lengths(B2, v[i], v[j], M[i], v[0], q, M[0]) == Sign::negative) return false;
  return true;
}

}  // namespace anisocert::predicates
