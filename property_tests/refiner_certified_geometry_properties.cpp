// The refiners' certified geometry (refiners/common/): Voronoi vertices and signs at them against
// the oracle's exact common points of the two bisector conics (oracle/algebraic, an independent
// engine: resultants and Sturm sequences, no Krawczyk): every box holds exactly one exact point; a
// complete search misses none in its box; an incomplete one occurs only where the exact curves
// touch (a multiple point) or share a component; every decided sign is the exact sign, and a sign
// is left undecided only where the exact value is zero. Then the order along a bisector conic
// (bisector_conic.hpp) against the curve's own geometry: the piece of each point against the exact
// sign of ∂B/∂y at the oracle's point, and the order of travel against orientations (a convex curve
// turns one way, the way its Hessian along the tangent says).

#include "oracle/algebraic/conic_intersection.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/bisector_conic.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>

using anisocert::FilterInterval;
using anisocert::Rational;
using anisocert::Sign;
using namespace anisocert::refiners::common;
using anisocert::oracle::AlgebraicPoint;
using anisocert::oracle::Conic;
using anisocert::oracle::RealAlgebraic;

namespace {

// Q_v − Q_w expanded, exactly (LS Proposition 2), from the doubles the sites are.
Conic bisector(const MetricSite& v, const MetricSite& w) {
  const auto q = [](const MetricSite& s, int k) {
    const Rational m11(s.M.m11), m12(s.M.m12), m22(s.M.m22), x(s.p.x), y(s.p.y);
    const Rational c[6] = {m11, 2 * m12, m22, -2 * (m11 * x + m12 * y), -2 * (m12 * x + m22 * y),
                           m11 * x * x + 2 * m12 * x * y + m22 * y * y};
    return c[k];
  };
  Rational c[6];
  for (int k = 0; k < 6; ++k) c[k] = q(v, k) - q(w, k);
  return {c[0], c[1], c[2], c[3], c[4], c[5]};
}

bool positive_definite(const Sym2<double>& M) {
  return M.m11 > 0 && anisocert::predicates::orientation<double>({0, 0}, {M.m11, M.m12}, {M.m12, M.m22}) == Sign::positive;
}

// A metric: eighths ("dyadic"), or a rotation of random axes computed in doubles ("rotated":
// entries that are no short fractions).
rc::Gen<Sym2<double>> metric() {
  return rc::gen::suchThat(
      rc::gen::oneOf(rc::gen::apply([](int a, int b, int c) { return Sym2<double>{a / 8.0, c / 8.0, b / 8.0}; },
                                    rc::gen::inRange(1, 65), rc::gen::inRange(1, 65), rc::gen::inRange(-32, 33)),
                     rc::gen::apply(
                         [](int angle, int l1, int l2) {
                           const double t = angle * 0.049, c = std::cos(t), s = std::sin(t);
                           const double a = std::ldexp(1.0, l1), b = std::ldexp(1.0, l2) * 1.37;
                           return Sym2<double>{a * c * c + b * s * s, (a - b) * c * s, a * s * s + b * c * c};
                         },
                         rc::gen::inRange(0, 128), rc::gen::inRange(-4, 5), rc::gen::inRange(-4, 5))),
      positive_definite);
}

rc::Gen<Point2<double>> point() {
  return rc::gen::apply([](int x, int y) { return Point2<double>{x / 16.0, y / 16.0}; }, rc::gen::inRange(-16, 17),
                        rc::gen::inRange(-16, 17));
}

struct Case {
  Trio t;
  MetricSite q;  // a fourth site, for signs
  std::string kind;
  double scale = 1;  // coordinates are multiples of 1/16 times this power of two
};

Sym2<double> mirrored(const Sym2<double>& M) { return {M.m11, -M.m12, M.m22}; }

// Generic trios; trios sharing one metric (straight bisectors, rational vertices); two sharing
// one; and mirror-symmetric quadruples a, b = a mirrored in x = 0, c, q = c mirrored, whose
// vertices on x = 0 (a subdivision line of the search box) are exactly equidistant from q too.
rc::Gen<Case> trio_case() {
  return rc::gen::mapcat(rc::gen::noShrink(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 4))), [](int k) -> rc::Gen<Case> {
    switch (k) {
      case 0:
        return rc::gen::apply(
            [](Point2<double> a, Point2<double> b, Point2<double> c, Point2<double> q, Sym2<double> A, Sym2<double> B,
               Sym2<double> C, Sym2<double> Q) { return Case{{{{a, A}, {b, B}, {c, C}}}, {q, Q}, "generic"}; },
            point(), point(), point(), point(), metric(), metric(), metric(), metric());
      case 1:
        return rc::gen::apply(
            [](Point2<double> a, Point2<double> b, Point2<double> c, Point2<double> q, Sym2<double> M) {
              return Case{{{{a, M}, {b, M}, {c, M}}}, {q, M}, "equal metrics"};
            },
            point(), point(), point(), point(), metric());
      case 2:
        return rc::gen::apply(
            [](Point2<double> a, Point2<double> b, Point2<double> c, Point2<double> q, Sym2<double> M, Sym2<double> C) {
              return Case{{{{a, M}, {b, M}, {c, C}}}, {q, C}, "two equal metrics"};
            },
            point(), point(), point(), point(), metric(), metric());
      default:
        return rc::gen::apply(
            [](Point2<double> a, Point2<double> c, Sym2<double> A, Sym2<double> C) {
              const Point2<double> b{-a.x, a.y}, q{-c.x, c.y};
              return Case{{{{a, A}, {b, mirrored(A)}, {c, C}}}, {q, mirrored(C)}, "mirror-symmetric"};
            },
            point(), point(), metric(), metric());
    }
  });
}

// A third of the cases moved to another magnitude: coordinates times 2^k (k in −30..30), metrics
// times 2^j (j in −20..20). Powers of two keep every double exact, so the geometry is the same.
rc::Gen<Case> scaled_case() {
  return rc::gen::apply(
      [](Case c, int k, int j, int pick) {
        if (pick != 0) return c;
        const double s = std::ldexp(1.0, k), m = std::ldexp(1.0, j);
        for (MetricSite* site : {&c.t[0], &c.t[1], &c.t[2], &c.q}) {
          site->p = {site->p.x * s, site->p.y * s};
          site->M = {site->M.m11 * m, site->M.m12 * m, site->M.m22 * m};
        }
        c.scale = s;
        c.kind += ", scaled";
        return c;
      },
      trio_case(), rc::gen::inRange(-30, 31), rc::gen::inRange(-20, 21), rc::gen::inRange(0, 3));
}

std::ostream& operator<<(std::ostream& os, const MetricSite& s) {
  return os << "(" << s.p.x << ", " << s.p.y << ") [" << s.M.m11 << ", " << s.M.m12 << ", " << s.M.m22 << "]";
}
std::ostream& operator<<(std::ostream& os, const Case& c) {
  return os << c.kind << ": " << c.t[0] << " " << c.t[1] << " " << c.t[2] << " q " << c.q;
}

bool distinct(const Case& c) {
  const auto same = [](const MetricSite& u, const MetricSite& v) { return u.p.x == v.p.x && u.p.y == v.p.y; };
  return !same(c.t[0], c.t[1]) && !same(c.t[0], c.t[2]) && !same(c.t[1], c.t[2]) && !same(c.q, c.t[0]) &&
         !same(c.q, c.t[1]) && !same(c.q, c.t[2]);
}

Sign cmp(const RealAlgebraic& a, double d) { return compare(a, RealAlgebraic::rational(Rational(d))); }
bool in_interval(const RealAlgebraic& a, const FilterInterval& i) {
  return cmp(a, i.lo) != Sign::negative && cmp(a, i.hi) != Sign::positive;
}
bool in_box(const AlgebraicPoint& p, const Box2<FilterInterval>& b) { return in_interval(p.x(), b.x) && in_interval(p.y(), b.y); }
bool strictly_in(const AlgebraicPoint& p, const Box2<FilterInterval>& b) {
  return cmp(p.x(), b.x.lo) == Sign::positive && cmp(p.x(), b.x.hi) == Sign::negative && cmp(p.y(), b.y.lo) == Sign::positive &&
         cmp(p.y(), b.y.hi) == Sign::negative;
}

// The exact points equidistant from a case's three sites (the oracle's common points of B_ab and
// B_ac), for cases of distinct sites whose two conics share no component.
anisocert::oracle::ConicIntersection exact_vertices(const Case& c) {
  RC_PRE(distinct(c));
  auto exact = anisocert::oracle::intersect(bisector(c.t[0], c.t[1]), bisector(c.t[0], c.t[2]));
  RC_PRE(!exact.shared_component);
  return exact;
}

Box2<FilterInterval> search_for(const Case& c) { return {{-4 * c.scale, 4 * c.scale}, {-4 * c.scale, 4 * c.scale}}; }

}  // namespace

namespace {

// A search of `box` against the exact points: every box it gives holds exactly one of them, and so
// does its isolating box; a complete search finds every point strictly inside `box`; only a
// tangency (a multiple point) can leave it incomplete.
void check_search(const VertexSearch& ours, const anisocert::oracle::ConicIntersection& exact, const Box2<FilterInterval>& box) {
  bool multiple = false;
  for (const auto& p : exact.points) multiple = multiple || p.multiplicity > 1;
  if (!ours.complete) {
    RC_TAG("incomplete");
    RC_ASSERT(multiple);
  }
  for (const VertexBox& v : ours.vertices) {
    int held = 0;
    for (const auto& p : exact.points) held += in_box(p.point, v.box);
    RC_ASSERT(held == 1);
    int isolated = 0;
    for (const auto& p : exact.points) isolated += in_box(p.point, v.isolating);
    RC_ASSERT(isolated == 1);
  }
  if (ours.complete)
    for (const auto& p : exact.points) {
      if (!strictly_in(p.point, box)) continue;
      int found = 0;
      for (const VertexBox& v : ours.vertices) found += in_box(p.point, v.box);
      RC_ASSERT(found == 1);
    }
}

}  // namespace

RC_GTEST_PROP(RefinerVoronoiVertex, BoxesHoldExactlyTheEquidistantPoints, ()) {
  const Case c = *scaled_case();
  RC_PRE(distinct(c));
  RC_TAG(c.kind);
  const auto exact = anisocert::oracle::intersect(bisector(c.t[0], c.t[1]), bisector(c.t[0], c.t[2]));
  const VertexSearch ours = vertices_in(c.t, search_for(c));
  if (exact.shared_component) {  // infinitely many points: no search may call itself complete
    RC_TAG("shared component");
    RC_ASSERT(!ours.complete || ours.vertices.empty());
    return;
  }
  RC_TAG(std::to_string(ours.vertices.size()) + " found");
  check_search(ours, exact, search_for(c));
}

// Three sites on the line x = 0 with metrics diag(1, dᵢ): d_a² − d_b² is a function of y alone,
// so det ½J vanishes everywhere (VertexSearch::singular). Here the pairs' equidistant lines are
// y = 2 ± √2 (sites 0, 1) and y = 2, 6 (sites 0, 2), closed forms: no point is equidistant from
// all three. A search over y ∈ [0, 4], where each difference has zeros, used to stop undecided at
// the first box (found by RefinerVoronoiVertex.BoxesHoldExactlyTheEquidistantPoints, seed 115);
// halving the box now excludes it.
TEST(RefinerVoronoiVertex, SingularTrioWithNoEquidistantPointIsExcluded) {
  const Trio t{{{{0, 0}, {1, 0, 1}}, {{0, 1}, {1, 0, 2}}, {{0, 3}, {1, 0, 4}}}};
  EXPECT_TRUE(anisocert::oracle::intersect(bisector(t[0], t[1]), bisector(t[0], t[2])).points.empty());
  const VertexSearch search = vertices_in(t, {FilterInterval(-1, 1), FilterInterval(0, 4)});
  EXPECT_TRUE(search.singular);
  EXPECT_TRUE(search.complete);
  EXPECT_TRUE(search.vertices.empty());
  // The third site at (0, c), c = 0.87867, with diag(1, 4): the lines of sites 0 and 2 are
  // y = 2c/3 and y = 2c, and 2c/3 = 0.58578 is 6·10⁻⁶ from 2 − √2. Halving each box across its
  // wider side needed more than the 256 boxes, and the search stayed undecided although no point is
  // equidistant (BoxesHoldExactlyTheEquidistantPoints asks for exactly this); across the side along
  // which F changes, 37.
  // And with the third site at (0, 1.5), the lines are y = 1, 3: at the box's midpoint y = 2 both
  // differences have ∂/∂y = 0 exactly (2 − 2·1 and 2 − 4·½). A review argued that a direction read
  // at the midpoint would then choose x every time; in doubles both derivatives' intervals are a
  // few ulps wide there and the search still succeeds, with either reading. The case is kept as a
  // degenerate input with a closed-form answer, not as proof of the enclosure over the part.
  for (const double c : {0.87867, 1.5}) {
    const Trio close{{{{0, 0}, {1, 0, 1}}, {{0, 1}, {1, 0, 2}}, {{0, c}, {1, 0, 4}}}};
    EXPECT_TRUE(anisocert::oracle::intersect(bisector(close[0], close[1]), bisector(close[0], close[2])).points.empty());
    const VertexSearch near = vertices_in(close, {FilterInterval(-1, 1), FilterInterval(0, 4)});
    EXPECT_TRUE(near.singular) << c;
    EXPECT_TRUE(near.complete) << c << ": " << near.boxes;
    EXPECT_TRUE(near.vertices.empty()) << c;
  }
}

RC_GTEST_PROP(RefinerVoronoiVertex, SignsAtVerticesAreTheExactSigns, ()) {
  const Case c = *scaled_case();
  const auto exact = exact_vertices(c);
  const VertexSearch ours = vertices_in(c.t, search_for(c));
  const Conic g = bisector(c.q, c.t[0]);
  for (const VertexBox& v : ours.vertices) {
    const CertifiedPoint vertex(c.t, v);
    const auto ours_sign = sign_at<1>({&vertex}, [&](const auto& p, auto of) {
      using T = std::decay_t<decltype(p[0].x)>;
      return distance2(lift<T>(c.q, of), p[0].x, p[0].y) - distance2(lift<T>(c.t[0], of), p[0].x, p[0].y);
    });
    for (const auto& p : exact.points) {
      if (!in_box(p.point, v.box)) continue;
      const Sign s = p.point.sign_of(g.polynomial());
      RC_TAG(c.kind + (s == Sign::zero ? ", exact tie" : ""));
      if (ours_sign)
        RC_ASSERT(*ours_sign == s);
      else
        RC_ASSERT(s == Sign::zero);  // undecided only on a tie
      if (c.kind.rfind("equal metrics", 0) == 0) RC_ASSERT(ours_sign.has_value());  // a rational vertex decides ties too
    }
  }
}

// Signs of expressions in two points (here x₁ − x₂ of two vertices, or of a vertex and a double
// point) against the oracle's exact comparison.
RC_GTEST_PROP(RefinerVoronoiVertex, SignsAtTwoPointsAreTheExactSigns, ()) {
  const Case c = *scaled_case();
  const auto exact = exact_vertices(c);
  const VertexSearch ours = vertices_in(c.t, search_for(c));
  // Each vertex against every other and against the double point at its box's midpoint.
  std::vector<std::pair<CertifiedPoint, AlgebraicPoint>> points;
  for (const VertexBox& v : ours.vertices)
    for (const auto& p : exact.points)
      if (in_box(p.point, v.box)) {
        points.emplace_back(CertifiedPoint(c.t, v), p.point);
        const Point2<double> m = v.approx();
        points.emplace_back(CertifiedPoint(m), AlgebraicPoint::rational(Rational(m.x), Rational(m.y)));
      }
  int ties = 0;
  for (const auto& [a, ea] : points)
    for (const auto& [b, eb] : points) {
      const auto s = sign_at<2>({&a, &b}, [](const auto& p, auto) { return p[0].x - p[1].x; });
      const Sign e = anisocert::oracle::compare_x(ea, eb);
      ties += &a != &b && e == Sign::zero;
      if (s)
        RC_ASSERT(*s == e);
      else
        RC_ASSERT(e == Sign::zero);
    }
  RC_TAG(ties ? "two points with equal x" : "no two points with equal x");
}

RC_GTEST_PROP(RefinerVoronoiVertex, EnclosuresAtHighPrecisionHoldThePointAndShrink, ()) {
  const Case c = *scaled_case();
  const auto exact = exact_vertices(c);
  for (const VertexBox& v : vertices_in(c.t, search_for(c)).vertices) {
    const Box2<anisocert::Interval> X = enclose(c.t, v, 512);
    for (const auto& p : exact.points) {
      if (!in_box(p.point, v.box)) continue;
      // The exact point lies in X: compare with X's ends rounded outward to rationals.
      const auto holds = [](const RealAlgebraic& a, const anisocert::Interval& i) {
        Rational lo, hi;
        mpfr_get_q(lo.backend().data(), i.lower());
        mpfr_get_q(hi.backend().data(), i.upper());
        return compare(a, RealAlgebraic::rational(lo)) != Sign::negative && compare(a, RealAlgebraic::rational(hi)) != Sign::positive;
      };
      RC_ASSERT(holds(p.point.x(), X.x));
      RC_ASSERT(holds(p.point.y(), X.y));
      // Width below 2⁻⁴⁰⁰ times the size of the coordinates: Krawczyk's contraction worked.
      mpfr_t w;
      mpfr_init2(w, 512);
      mpfr_sub(w, X.x.upper(), X.x.lower(), MPFR_RNDU);
      const double wx = mpfr_get_d(w, MPFR_RNDU);
      mpfr_sub(w, X.y.upper(), X.y.lower(), MPFR_RNDU);
      const double wy = mpfr_get_d(w, MPFR_RNDU);
      mpfr_clear(w);
      const double scale = c.scale + std::abs(v.approx().x) + std::abs(v.approx().y);
      RC_ASSERT(wx <= std::ldexp(scale, -400));
      RC_ASSERT(wy <= std::ldexp(scale, -400));
    }
  }
}

// The enclosures Krawczyk's operator is built on: F on a box (the exact quadratic expansion) and
// ½J on a box contain the exact values at every rational point of the box.
RC_GTEST_PROP(RefinerVoronoiVertex, EnclosuresOnBoxesHoldTheExactValues, ()) {
  const Case c = *scaled_case();
  const int e = *rc::gen::inRange(-40, 3);  // box half-width 2^e · scale
  const double cx = *rc::gen::inRange(-64, 65) / 16.0 * c.scale, cy = *rc::gen::inRange(-64, 65) / 16.0 * c.scale;
  const double r = std::ldexp(c.scale, e);
  const Box2<FilterInterval> X{{cx - r, cx + r}, {cy - r, cy + r}};
  RC_PRE(X.x.lo < X.x.hi && X.y.lo < X.y.hi);
  const auto fi = [](double d) { return FilterInterval(d); };
  const auto q = [](double d) { return Rational(d); };
  const Equidistance<FilterInterval> F({lift<FilterInterval>(c.t[0], fi), lift<FilterInterval>(c.t[1], fi), lift<FilterInterval>(c.t[2], fi)});
  const Equidistance<Rational> E({lift<Rational>(c.t[0], q), lift<Rational>(c.t[1], q), lift<Rational>(c.t[2], q)});
  const auto on = F.on(X);
  const FilterInterval mx = X.x.midpoint(), my = X.y.midpoint();
  const auto J = F.half_jacobian(F.half_jacobian(mx, my), X.x - mx, X.y - my);
  const auto holds = [](const FilterInterval& i, const Rational& v) { return Rational(i.lo) <= v && v <= Rational(i.hi); };
  for (int k = 0; k < 8; ++k) {  // corners, the centre and random points: (cx + r·s/64, cy + r·t/64)
    const int s = *rc::gen::inRange(-64, 65), t = *rc::gen::inRange(-64, 65);
    const Rational x = Rational(cx) + Rational(r) * Rational(k < 4 ? (k & 1 ? 64 : -64) : s, 64);
    const Rational y = Rational(cy) + Rational(r) * Rational(k < 4 ? (k & 2 ? 64 : -64) : t, 64);
    const auto v = E.at(x, y);
    RC_ASSERT(holds(on[0], v[0]));
    RC_ASSERT(holds(on[1], v[1]));
    const auto g = E.half_jacobian(x, y);
    for (int i = 0; i < 4; ++i) RC_ASSERT(holds(J[static_cast<std::size_t>(i)], g[static_cast<std::size_t>(i)]));
  }
}

// det ½J as a polynomial (Equidistance::jacobian_determinant, which decides singular trios) is the
// determinant of ½J itself at rational points, exactly; and a search calls a trio singular exactly
// when all six coefficients are zero.
RC_GTEST_PROP(RefinerVoronoiVertex, JacobianDeterminantIsTheDeterminantOfHalfJ, ()) {
  const Case c = *scaled_case();
  const auto q = [](double d) { return Rational(d); };
  const Equidistance<Rational> E({lift<Rational>(c.t[0], q), lift<Rational>(c.t[1], q), lift<Rational>(c.t[2], q)});
  const auto k = E.jacobian_determinant();
  for (int i = 0; i < 4; ++i) {
    const Rational x(*rc::gen::inRange(-1000, 1001), 97), y(*rc::gen::inRange(-1000, 1001), 89);
    const auto J = E.half_jacobian(x, y);
    RC_ASSERT(J[0] * J[3] - J[1] * J[2] == k[0] * x * x + k[1] * x * y + k[2] * x + k[3] * y * y + k[4] * y + k[5]);
  }
  const bool zero = std::all_of(k.begin(), k.end(), [](const Rational& v) { return v == 0; });
  const VertexSearch search = vertices_in(c.t, {FilterInterval(-1, 1), FilterInterval(-1, 1)}, 16);
  RC_ASSERT(!search.singular || zero);
  if (zero && !(c.t[0].M == c.t[1].M && c.t[0].M == c.t[2].M)) RC_ASSERT(search.singular);  // equal metrics: answered before
  // Three sites on one line x = x₀ with metrics diag(a, dᵢ): the first column of ½J is
  // a(x − x₀) − a(x − x₀) = 0 everywhere, so det ½J ≡ 0.
  const double x0 = *rc::gen::inRange(-64, 65) / 16.0, a = *rc::gen::inRange(1, 1000) / 8.0;
  Trio column;
  for (int i = 0; i < 3; ++i)
    column[static_cast<std::size_t>(i)] = {{x0, (*rc::gen::inRange(-64, 65) + 200 * i) / 16.0}, {a, 0, *rc::gen::inRange(1, 1000) / 8.0}};
  RC_PRE(!(column[0].M == column[1].M && column[0].M == column[2].M));
  RC_ASSERT(vertices_in(column, {FilterInterval(-100, 100), FilterInterval(-100, 100)}).singular);
}

// Krawczyk's verdicts against the exact count of points in the box: none ⇒ 0, unique ⇒ 1. Boxes
// of every size, many hugging an exact vertex (centred at its double box, width 2^e).
RC_GTEST_PROP(RefinerVoronoiVertex, KrawczykVerdictsAgreeWithTheExactCount, ()) {
  const Case c = *scaled_case();
  const auto exact = exact_vertices(c);
  const VertexSearch found = vertices_in(c.t, search_for(c));
  double cx = *rc::gen::inRange(-64, 65) / 16.0 * c.scale, cy = *rc::gen::inRange(-64, 65) / 16.0 * c.scale;
  if (!found.vertices.empty() && *rc::gen::inRange(0, 2) == 0) {  // hug a vertex
    const auto a = found.vertices[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(found.vertices.size())))].approx();
    cx = a.x + std::ldexp(c.scale, -50) * *rc::gen::inRange(-8, 9), cy = a.y + std::ldexp(c.scale, -50) * *rc::gen::inRange(-8, 9);
  }
  const double r = std::ldexp(c.scale, *rc::gen::inRange(-48, 3));
  const Box2<FilterInterval> X{{cx - r, cx + r}, {cy - r, cy + r}};
  RC_PRE(X.x.lo < X.x.hi && X.y.lo < X.y.hi);
  const auto fi = [](double d) { return FilterInterval(d); };
  const Equidistance<FilterInterval> F({lift<FilterInterval>(c.t[0], fi), lift<FilterInterval>(c.t[1], fi), lift<FilterInterval>(c.t[2], fi)});
  const KrawczykStep<FilterInterval> k = krawczyk(F, X, FilterInterval(1.0));
  int inside = 0;
  for (const auto& p : exact.points) inside += in_box(p.point, X);
  RC_TAG(k.verdict == KrawczykVerdict::no_zero ? "no zero" : k.verdict == KrawczykVerdict::unique_zero ? "unique zero" : "unknown");
  if (k.verdict == KrawczykVerdict::no_zero) RC_ASSERT(inside == 0);
  if (k.verdict == KrawczykVerdict::unique_zero) {
    RC_ASSERT(inside == 1);
    for (const auto& p : exact.points)
      if (in_box(p.point, X)) RC_ASSERT(in_box(p.point, k.box));  // and the zero is in K(X)
  }
  if (k.verdict == KrawczykVerdict::unknown)  // K(X) ∩ X keeps every zero of X
    for (const auto& p : exact.points)
      if (in_box(p.point, X)) RC_ASSERT(in_box(p.point, k.box));
}

// The same vertex found by two searches over different boxes is recognized as the same, and
// different vertices as different: same_vertex against the exact points.
RC_GTEST_PROP(RefinerVoronoiVertex, SameVertexAcrossSearchesIsTheExactEquality, ()) {
  const Case c = *scaled_case();
  const auto exact = exact_vertices(c);
  const double cx = *rc::gen::inRange(-32, 33) / 16.0 * c.scale, cy = *rc::gen::inRange(-32, 33) / 16.0 * c.scale;
  const double r = std::ldexp(c.scale, *rc::gen::inRange(-3, 3));
  const VertexSearch one = vertices_in(c.t, search_for(c)), two = vertices_in(c.t, {{cx - r, cx + r}, {cy - r, cy + r}});
  const auto point_of = [&](const VertexBox& v) {
    for (std::size_t i = 0; i < exact.points.size(); ++i)
      if (in_box(exact.points[i].point, v.box)) return i;
    return exact.points.size();
  };
  int decided = 0;
  for (const VertexBox& u : one.vertices)
    for (const VertexBox& v : two.vertices) {
      const auto same = same_vertex(u, v);
      if (!same) continue;
      ++decided;
      RC_ASSERT(*same == (point_of(u) == point_of(v)));
    }
  RC_TAG(decided ? "pairs decided" : "no pair");
}

namespace {

// Sites v and w, and third sites whose vertices with v and w are points of the conic B_vw.
struct ConicCase {
  MetricSite v, w;
  std::vector<MetricSite> others;
};

// M_w = M_v + (k/8) E for a fixed E: a line (E = 0), a parabola (E = [1 1; 1 1], singular, so
// b² = 4ac), a parabola that is a graph y(x) (E = diag(1, 0): c = b = 0), a hyperbola with a
// vertical asymptote (E = [1 1; 1 0]: c = 0, b ≠ 0), a hyperbola with axes along x and y
// (E = diag(1, −1)); or two unrelated metrics.
rc::Gen<ConicCase> conic_case() {
  return rc::gen::mapcat(rc::gen::noShrink(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 7))), [](int kind) -> rc::Gen<ConicCase> {
    const auto site = rc::gen::apply([](Point2<double> p, Sym2<double> M) { return MetricSite{p, M}; }, point(), metric());
    const auto others = rc::gen::container<std::vector<MetricSite>>(5, site);
    if (kind >= 5)
      return rc::gen::apply([](MetricSite a, MetricSite b, std::vector<MetricSite> o) { return ConicCase{a, b, o}; }, site, site, others);
    static const Sym2<double> E[5] = {{0, 0, 0}, {1, 1, 1}, {1, 0, 0}, {1, 1, 0}, {1, 0, -1}};
    return rc::gen::suchThat(
        rc::gen::apply(
            [kind](Point2<double> a, Point2<double> b, Sym2<double> M, int k, std::vector<MetricSite> o) {
              const double t = k / 8.0;
              const Sym2<double> N{M.m11 + t * E[kind].m11, M.m12 + t * E[kind].m12, M.m22 + t * E[kind].m22};
              return ConicCase{{a, M}, {b, N}, o};
            },
            point(), point(), metric(), rc::gen::inRange(-16, 17), others),
        [](const ConicCase& c) { return positive_definite(c.w.M); });
  });
}

std::ostream& operator<<(std::ostream& os, const ConicCase& c) {
  os << "v " << c.v << " w " << c.w << " others";
  for (const MetricSite& o : c.others) os << " " << o;
  return os;
}

const char* shape_name(BisectorConic::Shape s) {
  using S = BisectorConic::Shape;
  switch (s) {
    case S::line: return "line";
    case S::ellipse: return "ellipse";
    case S::hyperbola_two_ranges: return "hyperbola, two x-ranges";
    case S::hyperbola_two_branches: return "hyperbola, two branches";
    case S::hyperbola_vertical_asymptote: return "hyperbola, vertical asymptote";
    case S::parabola: return "parabola";
    case S::parabola_graph: return "parabola, a graph";
    default: return "degenerate";
  }
}

template <std::size_t N, class F>
Sign decided(const std::array<const CertifiedPoint*, N>& p, F f) {
  const auto s = sign_at<N>(p, f);
  RC_ASSERT(s.has_value());
  return *s;
}

}  // namespace

RC_GTEST_PROP(RefinerBisectorConic, TravelFollowsTheCurve, ()) {
  const ConicCase c = *conic_case();
  RC_PRE(!(c.v.p.x == c.w.p.x && c.v.p.y == c.w.p.y));
  const BisectorConic B(c.v, c.w);
  RC_TAG(shape_name(B.shape()));
  const Conic exact_b = bisector(c.v, c.w);
  {  // degenerate exactly when the conic's symmetric 3 × 3 matrix is singular (and not a line)
    const Rational A[3][3] = {{exact_b.a, exact_b.b / 2, exact_b.d / 2}, {exact_b.b / 2, exact_b.c, exact_b.e / 2},
                              {exact_b.d / 2, exact_b.e / 2, exact_b.f}};
    const Rational det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                         A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    const bool line = exact_b.a == 0 && exact_b.b == 0 && exact_b.c == 0 && (exact_b.d != 0 || exact_b.e != 0);
    RC_ASSERT((B.shape() == BisectorConic::Shape::degenerate) == (!line && det == 0));
  }
  if (B.shape() == BisectorConic::Shape::degenerate) return;
  const Conic b_y{0, 0, 0, exact_b.b, 2 * exact_b.c, exact_b.e};
  // The points of B_vw that are vertices with a third site, each with its exact point.
  std::vector<CertifiedPoint> points;
  std::vector<AlgebraicPoint> exact;
  for (const MetricSite& o : c.others) {
    if ((o.p.x == c.v.p.x && o.p.y == c.v.p.y) || (o.p.x == c.w.p.x && o.p.y == c.w.p.y)) continue;
    const Trio t{c.v, c.w, o};
    const auto all = anisocert::oracle::intersect(exact_b, bisector(c.v, o));
    if (all.shared_component) continue;
    const VertexSearch found = vertices_in(t, {{-8, 8}, {-8, 8}});
    if (!found.complete) {  // only where the curves touch (as above); then not this property's case
      bool multiple = false;
      for (const auto& p : all.points) multiple = multiple || p.multiplicity > 1;
      RC_ASSERT(multiple);
      RC_DISCARD("the curves touch");
    }
    for (const VertexBox& vb : found.vertices)
      for (const auto& p : all.points)
        if (in_box(p.point, vb.box)) points.emplace_back(t, vb), exact.push_back(p.point);
  }
  // Distinct points only: two third sites may share a vertex with v and w (four sites tied).
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (std::size_t j = i + 1; j < exact.size(); ++j) RC_PRE(!anisocert::oracle::same_point(exact[i], exact[j]));
  const std::size_t n = points.size();
  RC_TAG(std::to_string(std::min<std::size_t>(n, 4)) + (n >= 4 ? "+" : "") + " points");
  // Pieces: σ is the exact sign of ∂B/∂y at the exact point.
  for (std::size_t i = 0; i < n; ++i) {
    const auto piece = B.piece(points[i]);
    const int sigma = static_cast<int>(exact[i].sign_of(b_y.polynomial()));
    if (!piece) {  // undecided only at a vertical tangent (where the point joins two pieces)
      RC_ASSERT(sigma == 0);
      RC_DISCARD("a point at a vertical tangent");
    }
    if (B.shape() != BisectorConic::Shape::line) RC_ASSERT(piece->sigma == sigma);
  }
  const auto next = [&](std::size_t from, std::size_t without) {
    std::vector<const CertifiedPoint*> others;
    std::vector<std::size_t> index;
    for (std::size_t j = 0; j < n; ++j)
      if (j != from && j != without) others.push_back(&points[j]), index.push_back(j);
    const auto k = B.first_after(points[from], others);
    RC_ASSERT(k.has_value());
    return *k < 0 ? n : index[static_cast<std::size_t>(*k)];
  };
  const auto orient = [&](std::size_t i, std::size_t j, std::size_t k) {
    return decided<3>({&points[i], &points[j], &points[k]}, [](const auto& P, auto) {
      return (P[1].x - P[0].x) * (P[2].y - P[0].y) - (P[1].y - P[0].y) * (P[2].x - P[0].x);
    });
  };
  // Which way the curve turns at P when run with v on the left: sign of tᵀ ∇²B t, t = (−B_y, B_x).
  const auto turning = [&](std::size_t i) {
    return decided<1>({&points[i]}, [&](const auto& P, auto of) {
      using T = std::decay_t<decltype(P[0].x)>;
      const ConicIn<T> q = bisector_coefficients(lift<T>(c.v, of), lift<T>(c.w, of));
      const T bx = (q.a + q.a) * P[0].x + q.b * P[0].y + q.d, by = q.b * P[0].x + (q.c + q.c) * P[0].y + q.e;
      const T tx = -by, ty = bx;
      return (q.a + q.a) * tx * tx + (q.b + q.b) * tx * ty + (q.c + q.c) * ty * ty;
    });
  };
  // The connected component of each point, from its exact point: the branches of a hyperbola
  // are told apart by the sign of ∂B/∂y (σ) or of x − x* (two x-ranges, x* = −K/(2L), L > 0).
  const Rational L = exact_b.b * exact_b.b - 4 * exact_b.a * exact_b.c, K = 2 * exact_b.b * exact_b.e - 4 * exact_b.c * exact_b.d;
  const auto component = [&](std::size_t i) {
    using S = BisectorConic::Shape;
    switch (B.shape()) {
      case S::hyperbola_two_branches:
      case S::hyperbola_vertical_asymptote: return static_cast<int>(exact[i].sign_of(b_y.polynomial()));
      case S::hyperbola_two_ranges: return static_cast<int>(exact[i].sign_of(Conic{0, 0, 0, 2 * L, 0, K}.polynomial()));
      default: return 0;
    }
  };
  // The order of travel from the curve's own geometry, where a coordinate is monotone along it:
  // a parabola is a graph over the direction n across its axis (the axis runs along the null
  // vector of D = M_v − M_w); a hyperbola whose D is diagonal has its branches either side of its
  // centre's x (or y) and is monotone in y (or x) along each. The way along is the sign of the
  // tangent rot90 ∇B on that coordinate, at p. Nothing for other shapes.
  const Rational D11 = exact_b.a, D12 = exact_b.b / 2, D22 = exact_b.c;
  const auto truth = [&](std::size_t p) -> std::optional<std::size_t> {
    using S = BisectorConic::Shape;
    // The monotone coordinate n·x: n = −(D11, D12) or −(D12, D22) (a non-zero row of the singular
    // D, across the axis) for a parabola; (0, 1) or (1, 0) for the hyperbola. `row` picks it.
    int row = 0;  // 1: D's first row, 2: its second, 3: (0, 1), 4: (1, 0)
    std::function<int(std::size_t)> branch = [](std::size_t) { return 0; };
    if (B.shape() == S::parabola || B.shape() == S::parabola_graph) {
      row = D11 != 0 || D12 != 0 ? 1 : 2;
    } else if ((B.shape() == S::hyperbola_two_ranges || B.shape() == S::hyperbola_two_branches) && D12 == 0) {
      const Rational Bc = exact_b.f - exact_b.d * exact_b.d / (4 * D11) - exact_b.e * exact_b.e / (4 * D22);
      const bool by_x = anisocert::sign_of(D11) != anisocert::sign_of(Bc);  // a δx² = −B(c) − c δy² > 0: branches either side of c_x
      const Conic side = by_x ? Conic{0, 0, 0, 2 * D11, 0, exact_b.d} : Conic{0, 0, 0, 0, 2 * D22, exact_b.e};
      branch = [&exact, side](std::size_t i) { return static_cast<int>(exact[i].sign_of(side.polynomial())); };
      row = by_x ? 3 : 4;
    } else {
      return std::nullopt;
    }
    const auto n_of = [&](auto of) {
      using T = decltype(of(0.0));
      const T d11 = of(c.v.M.m11) - of(c.w.M.m11), d12 = of(c.v.M.m12) - of(c.w.M.m12), d22 = of(c.v.M.m22) - of(c.w.M.m22);
      switch (row) {
        case 1: return std::array<T, 2>{-d11, -d12};
        case 2: return std::array<T, 2>{-d12, -d22};
        case 3: return std::array<T, 2>{of(0.0), of(1.0)};
        default: return std::array<T, 2>{of(1.0), of(0.0)};
      }
    };
    // Which way along n the curve runs at p: the sign of the tangent (−B_y, B_x) on n.
    const int way = static_cast<int>(decided<1>({&points[p]}, [&](const auto& P, auto of) {
      using T = std::decay_t<decltype(P[0].x)>;
      const ConicIn<T> q = bisector_coefficients(lift<T>(c.v, of), lift<T>(c.w, of));
      const T bx = (q.a + q.a) * P[0].x + q.b * P[0].y + q.d, by = q.b * P[0].x + (q.c + q.c) * P[0].y + q.e;
      const auto nv = n_of(of);
      return nv[1] * bx - nv[0] * by;
    }));
    RC_ASSERT(way != 0);
    const auto key = [&](std::size_t k, std::size_t l) {  // sign of n·(X_k − X_l)
      return static_cast<int>(decided<2>({&points[k], &points[l]}, [&](const auto& P, auto of) {
        const auto nv = n_of(of);
        return nv[0] * (P[0].x - P[1].x) + nv[1] * (P[0].y - P[1].y);
      }));
    };
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (i == p || branch(i) != branch(p)) continue;
      if (way * key(i, p) <= 0) continue;                      // behind p
      if (best == n || way * key(i, best) < 0) best = i;       // nearer than the best so far
    }
    return best;
  };
  const bool closed = B.shape() == BisectorConic::Shape::ellipse;
  bool against_truth = false;
  for (std::size_t p = 0; p < n; ++p) {
    const std::size_t a = next(p, n);
    if (const auto t = truth(p)) {
      RC_ASSERT(a == *t);
      against_truth = true;
    }
    if (closed && n >= 2) RC_ASSERT(a < n);  // a closed curve always comes to another point
    if (a == n) {  // p is the last of its component: every other point of it comes to p
      for (std::size_t x = 0; x < n; ++x) {
        if (x == p || component(x) != component(p)) continue;
        std::size_t at = x;
        for (std::size_t step = 0; step < n && at != p && at != n; ++step) at = next(at, n);
        RC_ASSERT(at == p);
      }
      continue;
    }
    RC_ASSERT(component(a) == component(p));
    if (closed) {  // every other point comes after a: P, A, X in the order the curve turns
      for (std::size_t x = 0; x < n; ++x)
        if (x != p && x != a) RC_ASSERT(orient(p, a, x) == turning(p));
      continue;
    }
    // An open curve never comes back, and a point's second is the first once the first is gone.
    const std::size_t b = next(a, n);
    RC_ASSERT(b != p);
    RC_ASSERT(next(p, a) == b);
    if (b < n && B.shape() != BisectorConic::Shape::line) RC_ASSERT(orient(p, a, b) == turning(p));
  }
  if (against_truth) RC_TAG("checked against a monotone coordinate");
}
