// LU Definitions 2.1 and 3.1–3.4, Lemmas 3.5, 3.7 and 3.8 in the plane, exactly. Delaunay
// triangulations for a metric M are computed by brute force here (a triangle is M-Delaunay
// when no other point is strictly inside its M-circumellipse), independently of any
// triangulation code of the project.

#include "predicates/distortion.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orientation.hpp"
#include "property_tests/generators/metrics.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>

using anisocert::Rational;
using namespace anisocert::predicates;
using anisocert::Sign;
using namespace anisocert::gen;

namespace {

using Points = std::vector<Point2<Rational>>;
using Triangle = std::array<int, 3>;  // counter-clockwise

// Sign of "d inside the M-circumellipse of triangle t" (t counter-clockwise).
Sign inside(const Points& P, const Triangle& t, const Point2<Rational>& d, const Sym2<Rational>& M) {
  return incircle(P[t[0]], P[t[1]], P[t[2]], d, M);
}

// All M-Delaunay triangles; nothing when some triangle has a cocircular fourth point or three
// points are collinear (the triangulation is then not unique).
std::optional<std::set<Triangle>> delaunay(const Points& P, const Sym2<Rational>& M) {
  std::set<Triangle> T;
  const int n = static_cast<int>(P.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const Sign o = orientation(P[i], P[j], P[k]);
        if (o == Sign::zero) return std::nullopt;
        const Triangle t = o == Sign::positive ? Triangle{i, j, k} : Triangle{i, k, j};
        bool empty = true;
        for (int l = 0; l < n; ++l) {
          if (l == i || l == j || l == k) continue;
          const Sign s = inside(P, t, P[l], M);
          if (s == Sign::zero) return std::nullopt;
          empty = empty && s == Sign::negative;
        }
        if (empty) T.insert(t);
      }
  return T;
}

// LU Definition 3.2: the triangles of Del_{M_v} incident to v (Ω = the plane).
std::set<Triangle> star(const std::set<Triangle>& del, int v) {
  std::set<Triangle> S;
  for (const Triangle& t : del)
    if (t[0] == v || t[1] == v || t[2] == v) S.insert(t);
  return S;
}

// lo..hi−1 random points in [−10, 10]², then three far points whose triangle contains them all,
// so that every random point, and every point inserted in [−10, 10]², is interior: its star is
// a closed fan (the paper restricts to a domain Ω for the same reason).
rc::Gen<Points> points(int lo, int hi) {
  return rc::gen::mapcat(rc::gen::inRange(lo, hi), [](int n) {
    return rc::gen::map(rc::gen::container<Points>(n, point()), [](Points P) {
      P.push_back({-1000, -1000});
      P.push_back({1000, -900});
      P.push_back({0, 1100});
      return P;
    });
  });
}

}  // namespace

// LU Definition 2.1: Del_M is F⁻¹ of the Euclidean Delaunay triangulation of F(V), M = FᵀF:
// incircle_M(a, b, c, d) = det F⁻¹ · incircle_I(Fa, Fb, Fc, Fd) (det F > 0 here), also for four
// exactly M-cocircular points c + F⁻¹(r uᵢ).
RC_GTEST_PROP(LU_D21, InCircleForMIsEuclideanInCircleAfterF, ()) {
  const Tagged m = *metric();
  const bool cocircular = *rc::gen::inRange(0, 3) == 0;
  Points P = *rc::gen::container<Points>(4, point());
  if (cocircular) {
    const Rational r = *rational_in(Rational(1, 10), Rational(5));
    const Point2<Rational> centre = P[0];
    for (auto& p : P) p = at_distance(centre, m.F, r, *unit_vector());
  }
  RC_TAG(cocircular ? "M-cocircular" : "generic");
  RC_TAG(m.kind);
  const Sym2<Rational> I{1, 0, 1};
  Points FP;
  for (const auto& p : P) FP.push_back(m.F.apply(p));
  RC_ASSERT(incircle(P[0], P[1], P[2], P[3], m.M) == incircle(FP[0], FP[1], FP[2], FP[3], I));
  RC_ASSERT(orientation(P[0], P[1], P[2]) == orientation(FP[0], FP[1], FP[2]));
  if (cocircular) RC_ASSERT(incircle(P[0], P[1], P[2], P[3], m.M) == Sign::zero);
}

// LU Lemma 3.5: the conflict zone Z_v (union of the M_v-circumdisks of the triangles of S_v)
// does not grow when a site is inserted. Checked at random points and at the centroids of
// the new star's triangles (which lie in the new zone): in the new zone ⇒ in the old one.
RC_GTEST_PROP(LU_L35, ConflictZoneDoesNotGrow, ()) {
  const Tagged m = *metric();
  Points P = *points(4, 9);
  const auto before = delaunay(P, m.M);
  RC_PRE(before.has_value());
  const std::set<Triangle> old_star = star(*before, 0);
  P.push_back(*point());
  const auto after = delaunay(P, m.M);
  RC_PRE(after.has_value());
  const std::set<Triangle> new_star = star(*after, 0);
  RC_TAG(new_star == old_star ? "star unchanged" : "star changed");
  Points probes = *rc::gen::container<Points>(20, point());
  for (const Triangle& t : new_star)
    probes.push_back({(P[t[0]].x + P[t[1]].x + P[t[2]].x) / 3, (P[t[0]].y + P[t[1]].y + P[t[2]].y) / 3});
  for (const auto& x : probes) {
    bool in_new = false, in_old = false;
    for (const Triangle& t : new_star) in_new = in_new || inside(P, t, x, m.M) == Sign::positive;
    for (const Triangle& t : old_star) in_old = in_old || inside(P, t, x, m.M) != Sign::negative;
    RC_ASSERT(!in_new || in_old);
  }
}

// LU Lemma 3.7 (2D): if d is strictly outside C_N(abc) and strictly inside C_N'(abc), the
// triangulations Del_N and Del_N' of {a, b, c, d} differ (the points are γ₀-cospherical).
RC_GTEST_PROP(LU_L37, DisagreeingMetricsGiveDifferentTriangulations, ()) {
  // a, b, c, d exactly N-cocircular, d then pushed out by 10⁻⁴⁰ (outside C_N); N' near N puts
  // it inside C_N' about half of the time.
  const auto [n1, n2] = *nearly_equal_pair();
  const Point2<Rational> centre = *point();
  const Rational r = *rational_in(Rational(1, 10), Rational(5));
  // Four distinct directions: u rotated by the rational rotations of angle 0, 2·atan(1/2),
  // 2·atan(1), 2·atan(2) (cos = (1 − t²)/(1 + t²), sin = 2t/(1 + t²)).
  const Point2<Rational> u = *unit_vector();
  Points P;
  for (const Rational& tn : {Rational(0), Rational(1, 2), Rational(1), Rational(2)}) {
    const Rational co = (1 - tn * tn) / (1 + tn * tn), si = 2 * tn / (1 + tn * tn);
    P.push_back(at_distance(centre, n1.F, r, {co * u.x - si * u.y, si * u.x + co * u.y}));
  }
  const Rational out = 1 + anisocert::gen::ten_to_minus(40);
  P[3] = {centre.x + out * (P[3].x - centre.x), centre.y + out * (P[3].y - centre.y)};
  RC_PRE(orientation(P[0], P[1], P[2]) != Sign::zero);
  const Triangle t = orientation(P[0], P[1], P[2]) == Sign::positive ? Triangle{0, 1, 2} : Triangle{0, 2, 1};
  RC_ASSERT(inside(P, t, P[3], n1.M) == Sign::negative);
  RC_PRE(inside(P, t, P[3], n2.M) == Sign::positive);
  const auto d1 = delaunay(P, n1.M), d2 = delaunay(P, n2.M);
  RC_PRE(d1 && d2);
  RC_ASSERT(*d1 != *d2);
  RC_ASSERT(d1->count(t) == 1 && d2->count(t) == 0);
}

// LU Lemma 3.8 (2D): a triangle τ = (v, w, x) of S_v (for M_v) that is not in S_w (for M_w) has
// a vertex p of S_w strictly inside C_{M_w}(τ) and not inside C_{M_v}(τ): v, w, x, p are
// γ₀-cospherical for M_v with N = M_v, N' = M_w (Lemma 3.7), γ₀ >= τ(v, w).
RC_GTEST_PROP(LU_L38, InconsistentTriangleHasACosphericalWitness, ()) {
  const Tagged mv = *metric(), mw = *metric();  // independent metrics: inconsistencies are common
  const Points P = *points(5, 9);  // v = P[0], w = P[1]
  const auto del_v = delaunay(P, mv.M), del_w = delaunay(P, mw.M);
  RC_PRE(del_v && del_w);
  const std::set<Triangle> Sv = star(*del_v, 0), Sw = star(*del_w, 1);
  std::set<int> vertices_of_Sw;
  for (const Triangle& t : Sw) vertices_of_Sw.insert(t.begin(), t.end());
  int inconsistent = 0;
  for (const Triangle& t : Sv) {
    const bool has_w = t[0] == 1 || t[1] == 1 || t[2] == 1;
    if (!has_w || Sw.count(t)) continue;
    ++inconsistent;
    bool witness = false;
    for (int p : vertices_of_Sw)
      witness = witness || (inside(P, t, P[p], mw.M) == Sign::positive && inside(P, t, P[p], mv.M) != Sign::positive);
    RC_ASSERT(witness);
  }
  RC_TAG(inconsistent ? "inconsistent triangle found" : "consistent");
}
