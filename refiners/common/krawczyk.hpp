#pragma once
// The points equidistant from three sites a, b, c (the candidates for a Voronoi vertex, LS §7)
// as the zeros of F(x) = (Q_a(x) − Q_b(x), Q_a(x) − Q_c(x)), for Krawczyk's operator
// (geometry/krawczyk.hpp) on a box of any interval type T.
//
// F is quadratic, so its expansion at m is exact: with δ = x − m and H₁ = M_a − M_b,
// H₂ = M_a − M_c (half the rows' Hessians),
//   F_i(x) = F_i(m) + ∇F_i(m)·δ + δᵀ H_i δ,   ½∇F_i(x) = ½∇F_i(m) + H_i δ.
// Evaluated on a box this form is much tighter than Q_a − Q_b term by term: where two metrics are
// equal (H_i = 0, a straight bisector) it is the exact range up to rounding.

#include "geometry/krawczyk.hpp"
#include "refiners/common/distance_function.hpp"

#include <optional>

namespace anisocert::refiners::common {

using geometry::Box2;
using geometry::krawczyk;
using geometry::KrawczykStep;
using geometry::KrawczykVerdict;

template <class T>
using SitesIn = std::array<SiteIn<T>, 3>;

// F of three sites, in T.
template <class T>
class Equidistance {
 public:
  explicit Equidistance(const SitesIn<T>& s)
      : s_(s),
        H_{Sym2<T>{s[0].m11 - s[1].m11, s[0].m12 - s[1].m12, s[0].m22 - s[1].m22},
           Sym2<T>{s[0].m11 - s[2].m11, s[0].m12 - s[2].m12, s[0].m22 - s[2].m22}} {}

  // F at a point (x and y are points of T).
  std::array<T, 2> at(const T& x, const T& y) const {
    const T qa = distance2(s_[0], x, y);
    return {qa - distance2(s_[1], x, y), qa - distance2(s_[2], x, y)};
  }

  // ½J at a point, row by row: M_a(x − a) − M_b(x − b), M_a(x − a) − M_c(x − c).
  std::array<T, 4> half_jacobian(const T& x, const T& y) const {
    const auto ga = half_gradient(s_[0], x, y), gb = half_gradient(s_[1], x, y), gc = half_gradient(s_[2], x, y);
    return {ga[0] - gb[0], ga[1] - gb[1], ga[0] - gc[0], ga[1] - gc[1]};
  }

  // ½J on the box m + δ, from ½J(m) (δ = X − m).
  std::array<T, 4> half_jacobian(const std::array<T, 4>& at_m, const T& dx, const T& dy) const {
    return {at_m[0] + (H_[0].m11 * dx + H_[0].m12 * dy), at_m[1] + (H_[0].m12 * dx + H_[0].m22 * dy),
            at_m[2] + (H_[1].m11 * dx + H_[1].m12 * dy), at_m[3] + (H_[1].m12 * dx + H_[1].m22 * dy)};
  }

  // det ½J as a polynomial in (x, y): its coefficients on x², xy, x, y², y, 1. ½J's rows are
  // H₁x + g₁ and H₂x + g₂ (g₁ = M_b b − M_a a, g₂ = M_c c − M_a a), so the determinant is a quadratic.
  // All six vanish, e.g., for three sites on one line x = const with metrics diag(a, dᵢ) of one a:
  // no point equidistant from them is then a simple zero of F.
  std::array<T, 6> jacobian_determinant() const {
    const auto g = [&](int k) {
      return std::array<T, 2>{(s_[k].m11 * s_[k].x + s_[k].m12 * s_[k].y) - (s_[0].m11 * s_[0].x + s_[0].m12 * s_[0].y),
                              (s_[k].m12 * s_[k].x + s_[k].m22 * s_[k].y) - (s_[0].m12 * s_[0].x + s_[0].m22 * s_[0].y)};
    };
    const auto g1 = g(1), g2 = g(2);
    // Rows as (p·X, q·X) with X = (x, y, 1).
    const std::array<T, 3> p1{H_[0].m11, H_[0].m12, g1[0]}, q1{H_[0].m12, H_[0].m22, g1[1]};
    const std::array<T, 3> p2{H_[1].m11, H_[1].m12, g2[0]}, q2{H_[1].m12, H_[1].m22, g2[1]};
    const auto c = [&](std::size_t i, std::size_t j) {
      const T diagonal = p1[i] * q2[j] - q1[i] * p2[j];
      return i == j ? diagonal : diagonal + (p1[j] * q2[i] - q1[j] * p2[i]);
    };
    return {c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)};
  }

  // F on the box X: the exact expansion at X's midpoint.
  std::array<T, 2> on(const Box2<T>& X) const {
    const T mx = X.x.midpoint(), my = X.y.midpoint();
    const T dx = X.x - mx, dy = X.y - my;
    const auto F = at(mx, my);
    const auto g = half_jacobian(mx, my);
    const T sx = sqr(dx), sy = sqr(dy), xy = dx * dy;
    const auto term = [&](int i) {
      const Sym2<T>& h = H_[i];
      return ((g[2 * i] * dx + g[2 * i + 1] * dy) + (g[2 * i] * dx + g[2 * i + 1] * dy)) +
             (h.m11 * sx + (h.m12 * xy + h.m12 * xy) + h.m22 * sy);
    };
    return {F[0] + term(0), F[1] + term(1)};
  }

 private:
  SitesIn<T> s_;
  std::array<Sym2<T>, 2> H_;
};

}  // namespace anisocert::refiners::common
