// LS Proposition 2 (the bisector is a conic), Definition 2 (the open wedge) and Lemma 3
// (visibility inside the wedge, and its tightness), on exactly constructed configurations:
// v = q + F_v⁻¹(r u), w = q + F_w⁻¹(r u') puts q exactly on the bisector (d_v(q) = d_w(q) = r).

#include "predicates/bisector.hpp"
#include "predicates/wedge.hpp"
#include "property_tests/generators/metrics.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::Sign;
using anisocert::sign_of;
using namespace anisocert::gen;

namespace {

struct OnBisector {
  Point2<Rational> q, v, w;
  Tagged Mv, Mw;
};

rc::Gen<OnBisector> on_bisector() {
  return rc::gen::apply(
      [](Point2<Rational> q, std::pair<Tagged, Tagged> m, Rational r, Point2<Rational> u1, Point2<Rational> u2) {
        return OnBisector{q, at_distance(q, m.first.F, r, u1), at_distance(q, m.second.F, r, u2), m.first, m.second};
      },
      point(), metric_pair(), rational_in(Rational(1, 10), Rational(5)), unit_vector(), unit_vector());
}

// The bisector conic a x² + b xy + c y² + d x + e y + f of d_v(q)² − d_w(q)², expanded:
// qᵀ(M_v − M_w)q − 2qᵀ(M_v v − M_w w) + vᵀM_v v − wᵀM_w w (LS Proposition 2).
Rational conic_at(const Point2<Rational>& q, const Point2<Rational>& v, const Sym2<Rational>& A, const Point2<Rational>& w,
                  const Sym2<Rational>& B) {
  const Rational a = A.m11 - B.m11, b = 2 * (A.m12 - B.m12), c = A.m22 - B.m22;
  const Rational d = -2 * ((A.m11 * v.x + A.m12 * v.y) - (B.m11 * w.x + B.m12 * w.y));
  const Rational e = -2 * ((A.m12 * v.x + A.m22 * v.y) - (B.m12 * w.x + B.m22 * w.y));
  const Rational f = d2(A, v, {0, 0}) - d2(B, w, {0, 0});
  return a * q.x * q.x + b * q.x * q.y + c * q.y * q.y + d * q.x + e * q.y + f;
}

Point2<Rational> between(const Point2<Rational>& from, const Point2<Rational>& to, const Rational& t) {
  return {from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)};
}

}  // namespace

RC_GTEST_PROP(LS_P2, BisectorIsTheConic, ()) {
  const OnBisector c = *on_bisector();
  RC_TAG(c.Mv.kind);
  RC_PRE(!(c.v.x == c.w.x && c.v.y == c.w.y));
  RC_ASSERT(side_of_bisector(c.q, c.v, c.Mv.M, c.w, c.Mw.M) == Sign::zero);
  RC_ASSERT(conic_at(c.q, c.v, c.Mv.M, c.w, c.Mw.M) == 0);
  const Point2<Rational> x = *point();  // anywhere: the predicate is the sign of the conic
  RC_ASSERT(side_of_bisector(x, c.v, c.Mv.M, c.w, c.Mw.M) == sign_of(conic_at(x, c.v, c.Mv.M, c.w, c.Mw.M)));
}

// The wedge is open: its boundary lines and the sites themselves are outside; the midpoint of
// vw is always inside ((m − v)ᵀM_v(w − v) = d_v(w)²/2 > 0, and symmetrically).
RC_GTEST_PROP(LS_D2, WedgeIsOpenAndContainsTheMidpoint, ()) {
  const OnBisector c = *on_bisector();
  RC_PRE(!(c.v.x == c.w.x && c.v.y == c.w.y));
  const Sym2<Rational>& A = c.Mv.M;
  RC_ASSERT(wedge_position(between(c.v, c.w, Rational(1, 2)), c.v, A, c.w, c.Mw.M).inside());
  RC_ASSERT(!wedge_position(c.v, c.v, A, c.w, c.Mw.M).inside());
  RC_ASSERT(!wedge_position(c.w, c.v, A, c.w, c.Mw.M).inside());
  // On the line through v where (q − v)ᵀM_v(w − v) = 0: q = v + s·J·M_v(w − v), J a quarter turn.
  const Rational gx = A.m11 * (c.w.x - c.v.x) + A.m12 * (c.w.y - c.v.y);
  const Rational gy = A.m12 * (c.w.x - c.v.x) + A.m22 * (c.w.y - c.v.y);
  const Rational s = *rational_in(Rational(-3), Rational(3));
  const WedgePosition boundary = wedge_position(Point2<Rational>{c.v.x - s * gy, c.v.y + s * gx}, c.v, A, c.w, c.Mw.M);
  RC_ASSERT(boundary.toward_w == Sign::zero);
  RC_ASSERT(!boundary.inside() && boundary.on_v_side());
  // Behind v: q = v − t(w − v), t > 0.
  RC_ASSERT(wedge_position(between(c.v, c.w, -*rational_in(Rational(0), Rational(3))), c.v, A, c.w, c.Mw.M).on_v_side());
}

// LS Lemma 3: q in wedge(v, w) with d_v(q) <= d_w(q) ⇒ every q' = λq + (1−λ)v, 0 < λ < 1,
// satisfies the same three inequalities.
RC_GTEST_PROP(LS_L3, SiteSeesItsCellInsideTheWedge, ()) {
  const OnBisector c = *on_bisector();
  RC_PRE(!(c.v.x == c.w.x && c.v.y == c.w.y));
  // A point of v's restricted cell: along vw, then off it; or, a third of the time, the point
  // c.q that lies exactly on the bisector.
  const Point2<Rational> base = between(c.v, c.w, *rational_in(Rational(0), Rational(1)));
  const Rational s = *rational_in(Rational(-1), Rational(1));
  const Point2<Rational> q = *rc::gen::inRange(0, 3) == 0
                                 ? c.q
                                 : Point2<Rational>{base.x - s * (c.w.y - c.v.y), base.y + s * (c.w.x - c.v.x)};
  const WedgePosition where = wedge_position(q, c.v, c.Mv.M, c.w, c.Mw.M);
  const Sign side = side_of_bisector(q, c.v, c.Mv.M, c.w, c.Mw.M);
  RC_PRE(where.inside() && side != Sign::positive);
  RC_TAG(side == Sign::zero ? "q on the bisector" : "q inside the cell");
  const Point2<Rational> p = between(c.v, q, *rational_in(Rational(0), Rational(1)));
  RC_ASSERT(wedge_position(p, c.v, c.Mv.M, c.w, c.Mw.M).inside());
  RC_ASSERT(side_of_bisector(p, c.v, c.Mv.M, c.w, c.Mw.M) != Sign::positive);
}

// Tightness ("visibility stops precisely where the Voronoi surface exits the wedge"): for q
// on the bisector, f(λ) = d_v(p)² − d_w(p)² along p = v + λ(q − v) has f(1) = 0 and
// f'(1) = 2(q − w)ᵀM_w(v − w). Outside the wedge on w's side that is < 0, so points just
// before q are closer to w: v cannot see q. f(λ) = αλ² + βλ + γ₀ with γ₀ = −d_w(v)² < 0 has
// roots 1 and λ* = γ₀/α; the point at λ = (λ* + 1)/2 is strictly on w's side.
RC_GTEST_PROP(LS_L3, VisibilityStopsWhereTheBisectorLeavesTheWedge, ()) {
  const OnBisector c = *on_bisector();
  RC_PRE(!(c.v.x == c.w.x && c.v.y == c.w.y));
  const WedgePosition where = wedge_position(c.q, c.v, c.Mv.M, c.w, c.Mw.M);
  RC_TAG(where.inside() ? "inside" : where.toward_v == Sign::negative ? "outside, w's side" : "other");
  const Point2<Rational> dq{c.q.x - c.v.x, c.q.y - c.v.y};
  const Rational alpha = d2(c.Mv.M, {0, 0}, dq) - d2(c.Mw.M, {0, 0}, dq);
  const Rational gamma0 = -d2(c.Mw.M, c.v, c.w);
  // f'(1) = α − γ₀ equals 2(q − w)ᵀM_w(v − w): the wedge half decides visibility near q.
  const Rational slope = alpha - gamma0;
  RC_ASSERT(slope == 2 * bilinear_form(c.Mw.M.m11, c.Mw.M.m12, c.Mw.M.m22, Rational(c.q.x - c.w.x),
                                       Rational(c.q.y - c.w.y), Rational(c.v.x - c.w.x), Rational(c.v.y - c.w.y)));
  RC_ASSERT(sign_of(slope) == where.toward_v);
  if (where.toward_v == Sign::negative) {
    const Rational lambda_star = gamma0 / alpha;  // α − γ₀ < 0 < −γ₀ forces α < 0
    RC_ASSERT(lambda_star >= 0 && lambda_star < 1);
    const Point2<Rational> p = between(c.v, c.q, (lambda_star + 1) / 2);
    RC_ASSERT(side_of_bisector(p, c.v, c.Mv.M, c.w, c.Mw.M) == Sign::positive);
  } else if (where.toward_v == Sign::positive) {
    // f(1 − ε) = −ε(α − γ₀ − αε) < 0 for ε small enough: v sees the points just before q.
    const Rational eps = alpha > 0 ? std::min(Rational(1, 2), Rational(slope / (2 * alpha))) : Rational(1, 2);
    const Point2<Rational> p = between(c.v, c.q, 1 - eps);
    RC_ASSERT(side_of_bisector(p, c.v, c.Mv.M, c.w, c.Mw.M) == Sign::negative);
  }
}
