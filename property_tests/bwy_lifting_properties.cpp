// BWY Lemma 1: power(x̂, σ(p)) = ‖x̂‖² + d_p(x)², for d = 2 and d = 3, exactly; hence the
// power diagram of the lifted spheres restricted to {x̂} is the anisotropic Voronoi diagram
// (the power difference has the sign of the bisector predicate). And the refiners' Voronoi
// vertices (refiners/common/vertex_subdivision.hpp, which the BWY refiner uses instead of lifting)
// are Lemma 1's: points of the manifold on the 3-face of the power diagram of their sites' spheres.

#include "predicates/bisector.hpp"
#include "predicates/lifting.hpp"
#include "predicates/metric.hpp"
#include "property_tests/generators/fields.hpp"
#include "property_tests/generators/metrics.hpp"
#include "refiners/common/vertex_subdivision.hpp"

#include <set>

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

namespace {

// A closed rational interval: the range of a polynomial over a box, from above (no rounding).
struct Range {
  Rational lo, hi;
};
Range operator+(const Range& a, const Range& b) { return {a.lo + b.lo, a.hi + b.hi}; }
Range operator*(const Rational& c, const Range& a) { return c >= 0 ? Range{c * a.lo, c * a.hi} : Range{c * a.hi, c * a.lo}; }
Range operator*(const Range& a, const Range& b) {
  const Rational p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {std::min(std::min(p[0], p[1]), std::min(p[2], p[3])), std::max(std::max(p[0], p[1]), std::max(p[2], p[3]))};
}

// The range over the box X of power(x̂, σ_u) − power(x̂, σ_v) = −2⟨x̂, ĉ_u − ĉ_v⟩ + ‖ĉ_u‖² − r_u² − ‖ĉ_v‖² + r_v²,
// affine in the lifted point x̂ = (x, y, x², xy, y²) (BWY §3.1: the quadric bisectors become
// hyperplanes), each lifted coordinate's range taken over X.
Range power_difference(const LiftedSphere<2>& u, const LiftedSphere<2>& v, const Range& x, const Range& y) {
  const std::array<Range, 5> xhat{x, y, x * x, x * y, y * y};
  Rational constant = -u.radius2 + v.radius2;
  for (int k = 0; k < 5; ++k) constant += u.centre[static_cast<std::size_t>(k)] * u.centre[static_cast<std::size_t>(k)] -
                                          v.centre[static_cast<std::size_t>(k)] * v.centre[static_cast<std::size_t>(k)];
  Range r{constant, constant};
  for (int k = 0; k < 5; ++k) r = r + Rational(-2) * (u.centre[static_cast<std::size_t>(k)] - v.centre[static_cast<std::size_t>(k)]) * xhat[static_cast<std::size_t>(k)];
  return r;
}

}  // namespace

// Sites on the 1/128 grid of the unit square with metrics from a smooth random field, inserted in
// the refiners' subdivision: at every vertex it keeps, in its certified box, the powers of the
// three sites' lifted spheres can be equal (each difference's range holds 0: the box meets the
// 3-face's hyperplanes) and every other site's power is larger throughout (the difference's range
// is positive: the box is in the three's power cells). The ranges are rational, computed from the
// lifted spheres, not from the distances the subdivision uses.
RC_GTEST_PROP(BWY_L1, RefinersVerticesLieOnThreeFacesOfTheLiftedPowerDiagram, ()) {
  const auto f = random_smooth_field();
  const int n = *rc::gen::inRange(3, 25);
  std::set<std::pair<int, int>> used;
  anisocert::refiners::common::VertexSubdivision diagram({0, 1, 0, 1}, 0x1p-40);
  std::vector<LiftedSphere<2>> spheres;
  while (static_cast<int>(spheres.size()) < n) {
    int i = *rc::gen::inRange(0, 129), j = *rc::gen::inRange(0, 129);
    while (!used.insert({i, j}).second) i = (i + 1) % 129, j = i == 0 ? (j + 1) % 129 : j;  // small sizes repeat
    const auto M = f.at(i / 128.0, j / 128.0);
    diagram.insert({{i / 128.0, j / 128.0}, M});
    spheres.push_back(lifted_sphere<2>({Rational(i, 128), Rational(j, 128)}, {Rational(M.m11), Rational(M.m12), Rational(M.m22)}));
  }
  int checked = 0;
  for (const auto& v : diagram.vertices()) {
    if (v.holders == 0) continue;
    const Range x{Rational(v.box.box.x.lo), Rational(v.box.box.x.hi)}, y{Rational(v.box.box.y.lo), Rational(v.box.box.y.hi)};
    const auto& a = spheres[static_cast<std::size_t>(v.sites[0])];
    for (int k : {v.sites[1], v.sites[2]}) {
      const Range d = power_difference(spheres[static_cast<std::size_t>(k)], a, x, y);
      RC_ASSERT(d.lo <= 0 && d.hi >= 0);
    }
    for (std::size_t k = 0; k < spheres.size(); ++k) {
      if (std::find(v.sites.begin(), v.sites.end(), static_cast<int>(k)) != v.sites.end()) continue;
      RC_ASSERT(power_difference(spheres[k], a, x, y).lo > 0);
    }
    ++checked;
  }
  RC_CLASSIFY(checked > 10, "more than 10 vertices");
}
