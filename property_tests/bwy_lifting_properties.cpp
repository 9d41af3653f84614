// BWY Lemma 1: power(x̂, σ(p)) = ‖x̂‖² + d_p(x)², for d = 2 and d = 3, exactly; hence the
// power diagram of the lifted spheres restricted to {x̂} is the anisotropic Voronoi diagram
// (the power difference has the sign of the bisector predicate).

#include "predicates/bisector.hpp"
#include "predicates/lifting.hpp"
#include "predicates/metric.hpp"
#include "property_tests/generators/metrics.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::sign_of;
using namespace anisocert::gen;

namespace {

template <int d>
Rational norm2(const Vec<d>& x) {
  Rational s = 0;
  for (const Rational& c : x) s += c * c;
  return s;
}

// A 3×3 SPD metric as FᵀF with F upper triangular, positive diagonal.
rc::Gen<Upper<3>> metric3() {
  return rc::gen::map(rc::gen::container<std::array<Rational, 6>>(rational_in(Rational(-2), Rational(2))),
                      [](std::array<Rational, 6> f) {
                        const Rational a = abs(f[0]) + 1, b = f[1], c = f[2], d = abs(f[3]) + 1, e = f[4],
                                       g = abs(f[5]) + 1;  // F = [a b c; 0 d e; 0 0 g]
                        return Upper<3>{a * a, a * b, a * c, b * b + d * d, b * c + d * e, c * c + e * e + g * g};
                      });
}

}  // namespace

RC_GTEST_PROP(BWY_L1, PowerIsLiftedNormPlusAnisotropicDistance2D, ()) {
  const Tagged m = *metric();
  const Point2<Rational> p = *point(), x = *point();
  RC_TAG(m.kind);
  const Upper<2> M{m.M.m11, m.M.m12, m.M.m22};
  const Vec<5> xhat = lift<2>({x.x, x.y});
  RC_ASSERT(power<2>(xhat, lifted_sphere<2>({p.x, p.y}, M)) == norm2<5>(xhat) + d2(m.M, p, x));
}

RC_GTEST_PROP(BWY_L1, PowerIsLiftedNormPlusAnisotropicDistance3D, ()) {
  const Upper<3> M = *metric3();
  const auto p = *rc::gen::container<std::array<Rational, 3>>(rational_in(Rational(-10), Rational(10)));
  const auto x = *rc::gen::container<std::array<Rational, 3>>(rational_in(Rational(-10), Rational(10)));
  Metric3 metric(Sym3<Rational>{M[0], M[1], M[2], M[3], M[4], M[5]});  // checks it is SPD
  const Vec<9> xhat = lift<3>(x);
  RC_ASSERT(power<3>(xhat, lifted_sphere<3>(p, M)) ==
            norm2<9>(xhat) + metric.quadratic_form(x[0] - p[0], x[1] - p[1], x[2] - p[2]));
}

RC_GTEST_PROP(BWY_L1, PowerDiagramIsTheAnisotropicDiagram, ()) {
  const auto [mv, mw] = *metric_pair();
  const Point2<Rational> v = *point(), w = *point(), x = *point();
  RC_TAG(mv.kind);
  const Vec<5> xhat = lift<2>({x.x, x.y});
  const Rational pv = power<2>(xhat, lifted_sphere<2>({v.x, v.y}, {mv.M.m11, mv.M.m12, mv.M.m22}));
  const Rational pw = power<2>(xhat, lifted_sphere<2>({w.x, w.y}, {mw.M.m11, mw.M.m12, mw.M.m22}));
  RC_ASSERT(sign_of(pv - pw) == side_of_bisector(x, v, mv.M, w, mw.M));
}
