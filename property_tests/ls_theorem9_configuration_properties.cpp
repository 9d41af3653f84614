// LS Theorem 9 and Corollary 10 on configurations with an exactly known Voronoi vertex: q and
// r rational, each site vᵢ = q + F_i⁻¹(r uᵢ) exactly on its own M_{vᵢ}-circle of radius r
// around q, so d_{vᵢ}(q) = r for i = 1, 2, 3 and q is a vertex of the three-site diagram.
// Then with β >= r/ℓ, γ² >= τ(vᵢ, vⱼ)², 1 <= γ <= √2, β >= 1/√2 and χ > 0 (all rational):
//   Theorem 9: q is wedged, and every angle θ of v₁v₂v₃ has θ >= arcsin χ measured by some vⱼ;
//   Corollary 10: measured by any p with τ(p, vᵢ) <= γ, arcsin(χ/γ²) <= θ <= 2 arccos(χ/γ²).
// The angle bounds are decided exactly: θ >= arcsin s ⇔ θ >= 90° or sin²θ >= s², and
// θ <= 2 arccos c ⇔ cos θ >= cos(2 arccos c) = 2c² − 1. (Exact comparisons of sin², stronger
// than comparing with theory/'s certified arcsin, which the theory tests cover.)

#include "predicates/angle.hpp"
#include "predicates/orientation.hpp"
#include "predicates/distortion.hpp"
#include "predicates/length_compare.hpp"
#include "predicates/wedge.hpp"
#include "property_tests/generators/metrics.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::Sign;
using namespace anisocert::gen;

namespace {

const mpfr_prec_t prec = 200;

struct Configuration {
  Point2<Rational> q;
  std::array<Point2<Rational>, 3> v;
  std::array<Sym2<Rational>, 3> M;
  Rational r;
  std::string kind;
};

// Three metrics near a common one (distortion small enough for χ > 0 to be possible), and
// directions spread around q: uᵢ rotated by about 120° each, from one random unit vector.
rc::Gen<Configuration> configuration() {
  return rc::gen::apply(
      [](Point2<Rational> q, Tagged base, int k, std::array<int, 12> e, Rational r, std::array<int, 3> turn) {
        const Rational eps = ten_to_minus(k);
        Configuration c{q, {}, {}, r, base.kind};
        // Unit vectors near 0°, 120°, 240°: ((m²−n²), 2mn)/(m²+n²) with n/m ≈ tan(θ/2).
        const int mn[3][2] = {{10 + turn[0], turn[1] - 1}, {4 + turn[1], 7 + turn[2]}, {4 + turn[2], -7 - turn[0]}};
        for (int i = 0; i < 3; ++i) {
          Frame F{base.F.f11 + eps * e[4 * i], base.F.f12 + eps * e[4 * i + 1], base.F.f21 + eps * e[4 * i + 2],
                  base.F.f22 + eps * e[4 * i + 3]};
          if (F.det() <= 0) F = base.F;
          const int m = mn[i][0], n = mn[i][1];
          const Rational h = m * m + n * n;
          c.v[i] = at_distance(q, F, r, {Rational(m * m - n * n) / h, Rational(2 * m * n) / h});
          c.M[i] = F.metric();
        }
        return c;
      },
      point(), metric(), rc::gen::inRange(1, 4), rc::gen::container<std::array<int, 12>>(rc::gen::inRange(-3, 4)),
      rational_in(Rational(1, 10), Rational(5)), rc::gen::container<std::array<int, 3>>(rc::gen::inRange(0, 3)));
}

bool orientation_nonzero(const Configuration& c) { return orientation(c.v[0], c.v[1], c.v[2]) != Sign::zero; }

Rational sqrt_above(const Rational& x) { return rational_above(sqrt(anisocert::Interval(x, prec))); }

}  // namespace

RC_GTEST_PROP(LS_T9, ChiPositiveMakesTheVertexWedgedAndBoundsAngles, ()) {
  const Configuration c = *configuration();
  RC_TAG(c.kind);
  for (int i = 0; i < 3; ++i) RC_ASSERT(d2(c.M[i], c.v[i], c.q) == c.r * c.r);  // q is equidistant
  RC_PRE(orientation_nonzero(c));
  // ℓ² = min over ordered pairs of d_{vᵢ}(vⱼ)²; β = a rational >= r/ℓ and >= 1/√2.
  Rational l2 = d2(c.M[0], c.v[0], c.v[1]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) l2 = std::min(l2, d2(c.M[i], c.v[i], c.v[j]));
  Rational beta = sqrt_above(c.r * c.r / l2);
  if (2 * beta * beta < 1) beta = Rational(7072, 10000);
  RC_ASSERT(radius_edge_at_most(Rational(beta * beta), c.q, c.v, c.M));  // r/ℓ <= β, the predicate agrees
  RC_ASSERT(!radius_edge_at_most(Rational(c.r * c.r / l2 * (1 - ten_to_minus(20))), c.q, c.v, c.M));
  Rational g = 1;  // γ²
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) g = std::max(g, rational_above(tau_squared_enclosure(c.M[i], c.M[j], prec)));
  const Rational chi = 1 / (2 * beta) - (g - 1) * beta / 2;  // LS Theorem 9's χ (it needs only γ² = g)
  RC_PRE(g <= 2 && chi > 0);
  // q is wedged.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) RC_ASSERT(wedge_position(c.q, c.v[i], c.M[i], c.v[j], c.M[j]).inside());
  // Each angle is >= arcsin χ from the perspective of some vertex.
  for (int k = 0; k < 3; ++k) {
    const auto& a = c.v[(k + 1) % 3];
    const auto& b = c.v[k];
    const auto& d = c.v[(k + 2) % 3];
    bool some = false;
    for (int j = 0; j < 3; ++j) some = some || angle_at_least_arcsin(a, b, d, c.M[j], Rational(chi * chi));
    RC_ASSERT(some);
  }
  // Corollary 10, measured by p: a vertex's metric or a blend of two (blends keep τ <= γ).
  const int i = *rc::gen::inRange(0, 3), j = *rc::gen::inRange(0, 3);
  const Sym2<Rational> Mp{(c.M[i].m11 + c.M[j].m11) / 2, (c.M[i].m12 + c.M[j].m12) / 2, (c.M[i].m22 + c.M[j].m22) / 2};
  for (int n = 0; n < 3; ++n) RC_ASSERT(tau_at_most(Mp, c.M[n], g));
  const Rational cg = chi / g;  // χ/γ²
  for (int k = 0; k < 3; ++k) {
    const auto& a = c.v[(k + 1) % 3];
    const auto& b = c.v[k];
    const auto& d = c.v[(k + 2) % 3];
    RC_ASSERT(angle_at_least_arcsin(a, b, d, Mp, Rational(cg * cg)));
    RC_ASSERT(compare_angle_cos(a, b, d, Mp, Rational(2 * cg * cg - 1)) != Sign::negative);
  }
}
