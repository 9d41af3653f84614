#pragma once
// Krawczyk's operator for a system F(x) = 0 of two quadratic equations in two unknowns, on a box X
// of any interval type T (FilterInterval, or MPFI's Interval at any precision):
//   K(X) = m − Y F(m) + (I − Y J(X)) (X − m),
// for a point m of X and any matrix Y (here an approximate inverse of J(m)). Every zero of F in X
// lies in K(X); K(X) ⊂ int X proves that X holds exactly one (R. Krawczyk, Computing 4 (1969);
// A. Neumaier, Interval Methods for Systems of Equations (1990), §5.1). So K(X) ∩ X = ∅ proves
// that X holds none. These are the only conclusions drawn from it.
//
// F is given by its rows' values and half Jacobians (the system's own class: the refiners'
// three-site equidistance, refiners/common/krawczyk.hpp; the oracle's two conics,
// oracle/algebraic/narrowed_box.cpp):
//   F.at(x, y)                        F at a point, as std::array<T, 2>;
//   F.half_jacobian(x, y)             ½J at a point, row by row, as std::array<T, 4>;
//   F.half_jacobian(at_m, dx, dy)     ½J on the box m + δ from ½J(m) (F quadratic: exact in δ).
#include <array>
#include <optional>

namespace anisocert::geometry {

template <class T>
struct Box2 {
  T x, y;
};

enum class KrawczykVerdict {
  no_zero,      // K(X) ∩ X = ∅
  unique_zero,  // K(X) ⊂ int X
  unknown,      // neither: `box` is K(X) ∩ X, which holds every zero of X
};

template <class T>
struct KrawczykStep {
  KrawczykVerdict verdict;
  Box2<T> box;  // K(X) when unique, K(X) ∩ X when unknown
};

// One application of K to X. `one` is 1 in T.
template <class F2, class T>
KrawczykStep<T> krawczyk(const F2& F, const Box2<T>& X, const T& one) {
  const T mx = X.x.midpoint(), my = X.y.midpoint();
  const T dx = X.x - mx, dy = X.y - my;
  // Y = mid(½J(m))⁻¹; K with Y/2 in place of Y is then m − Y·(½F(m)) + (I − Y·½J(X))(X − m).
  const auto Jm = F.half_jacobian(mx, my);
  const T a = Jm[0].midpoint(), b = Jm[1].midpoint(), c = Jm[2].midpoint(), d = Jm[3].midpoint();
  const T det = a * d - b * c;
  if (det.has_zero()) return {KrawczykVerdict::unknown, X};
  const T y11 = (d / det).midpoint(), y12 = (-b / det).midpoint(), y21 = (-c / det).midpoint(), y22 = (a / det).midpoint();
  const auto Fm = F.at(mx, my);
  const T half = one / 2, hf0 = Fm[0] * half, hf1 = Fm[1] * half;
  const auto JX = F.half_jacobian(Jm, dx, dy);
  const T c11 = one - (y11 * JX[0] + y12 * JX[2]), c12 = -(y11 * JX[1] + y12 * JX[3]);
  const T c21 = -(y21 * JX[0] + y22 * JX[2]), c22 = one - (y21 * JX[1] + y22 * JX[3]);
  Box2<T> K{mx - (y11 * hf0 + y12 * hf1) + (c11 * dx + c12 * dy), my - (y21 * hf0 + y22 * hf1) + (c21 * dx + c22 * dy)};
  // No zero only when K(X) is certainly apart from X (a NaN end decides nothing).
  const auto apart = [](const T& k, const T& x) { return k.upper_double() < x.lower_double() || k.lower_double() > x.upper_double(); };
  if (apart(K.x, X.x) || apart(K.y, X.y)) return {KrawczykVerdict::no_zero, X};
  auto ix = intersection(K.x, X.x), iy = intersection(K.y, X.y);
  if (!ix || !iy) return {KrawczykVerdict::unknown, X};
  if (K.x.strictly_inside(X.x) && K.y.strictly_inside(X.y)) return {KrawczykVerdict::unique_zero, K};
  return {KrawczykVerdict::unknown, {*ix, *iy}};
}

}  // namespace anisocert::geometry
