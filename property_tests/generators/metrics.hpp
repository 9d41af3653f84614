#pragma once
// RapidCheck generators of metrics with rational square roots (M = FᵀF, F rational, det F > 0)
// and of exactly degenerate configurations built from them (DESIGN.md § Tests: shrinking
// keeps the degeneracy class, RC_TAG shows the mix).

#include "predicates/point.hpp"
#include "property_tests/generators/rationals.hpp"
#include "numbers/interval.hpp"

#include <string>
#include <utility>
#include <vector>

namespace anisocert::gen {

using predicates::Point2;
using predicates::Sym2;

struct Frame {  // F = [f11 f12; f21 f22], det F > 0
  Rational f11, f12, f21, f22;
  Rational det() const { return f11 * f22 - f12 * f21; }
  Sym2<Rational> metric() const;                               // FᵀF
  Point2<Rational> apply(const Point2<Rational>& x) const;     // F x
  Point2<Rational> inverse(const Point2<Rational>& u) const;   // F⁻¹ u
};

struct Tagged {
  Frame F;
  Sym2<Rational> M;  // = F.metric()
  std::string kind;
};

// Picks one of several generators, uniformly at every test size, by an index that never
// shrinks, so that shrinking a counterexample stays inside its class.
template <class T>
rc::Gen<T> one_of_classes(std::vector<rc::Gen<T>> gens) {
  const int n = static_cast<int>(gens.size());
  return rc::gen::mapcat(rc::gen::noShrink(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, n))),
                         [gens](int i) { return gens[i]; });
}

// A rational point on the unit circle, ((m²−n²), 2mn)/(m²+n²) with signs and order varied.
rc::Gen<Point2<Rational>> unit_vector();
// A rational point with short denominators in [−10, 10]².
rc::Gen<Point2<Rational>> point();
// "well_conditioned" (entries in [−2, 2]) or "anisotropic" (a rational rotation and axis
// ratio up to 1:10³, so eigenvalue ratios up to 1:10⁶).
rc::Gen<Tagged> metric();
// Two metrics: "generic", "nearly_equal" (F₂ = F₁ + 10⁻ᵏ E, k in 3..12) or "equal".
rc::Gen<std::pair<Tagged, Tagged>> metric_pair();
rc::Gen<std::pair<Tagged, Tagged>> nearly_equal_pair();

// A point at exact M-distance r from q: q + F⁻¹(r u), |u| = 1, so d_M(q, x) = r.
Point2<Rational> at_distance(const Point2<Rational>& q, const Frame& F, const Rational& r, const Point2<Rational>& u);

Rational d2(const Sym2<Rational>& M, const Point2<Rational>& a, const Point2<Rational>& b);  // d_M(a, b)²

// A certified enclosure of τ(P, Q)² = (B + √D)/m from its exact data (predicates::tau_squared).
anisocert::Interval tau_squared_enclosure(const Sym2<Rational>& P, const Sym2<Rational>& Q, mpfr_prec_t prec);

// A rational γ² >= τ(P, Q)², from a certified enclosure of τ².
Rational tau2_above(const Sym2<Rational>& P, const Sym2<Rational>& Q);

// A rational just above (or below) the certified enclosure x: its upper (lower) end in 30 digits.
Rational rational_above(const anisocert::Interval& x);
Rational rational_below(const anisocert::Interval& x);

}  // namespace anisocert::gen

namespace anisocert::predicates {
std::ostream& operator<<(std::ostream& os, const Point2<Rational>& p);
std::ostream& operator<<(std::ostream& os, const Sym2<Rational>& m);
}  // namespace anisocert::predicates

namespace anisocert::gen {
std::ostream& operator<<(std::ostream& os, const Tagged& t);
}
