// The refiners' certified Voronoi vertices (refiners/common/voronoi_vertex) against the oracle's
// exact common points of the two bisector conics (oracle/algebraic, an independent engine:
// resultants and Sturm sequences, no Krawczyk): every box holds exactly one exact point; a
// complete search misses none in its box; an incomplete one occurs only where the exact curves
// touch (a multiple point) or share a component; every decided sign is the exact sign, and a sign
// is left undecided only where the exact value is zero.

#include "oracle/algebraic/conic_intersection.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/certified_point.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

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

const Box2<FilterInterval> search{{-4, 4}, {-4, 4}};

}  // namespace

RC_GTEST_PROP(RefinerVoronoiVertex, BoxesHoldExactlyTheEquidistantPoints, ()) {
  const Case c = *trio_case();
  RC_PRE(distinct(c));
  RC_TAG(c.kind);
  const auto exact = anisocert::oracle::intersect(bisector(c.t[0], c.t[1]), bisector(c.t[0], c.t[2]));
  const VertexSearch ours = vertices_in(c.t, search);
  if (exact.shared_component) {
    RC_TAG("shared component");
    return;
  }
  bool multiple = false;
  for (const auto& p : exact.points) multiple = multiple || p.multiplicity > 1;
  RC_TAG(std::to_string(ours.vertices.size()) + " found");
  if (!ours.complete) {
    RC_TAG("incomplete");
    RC_ASSERT(multiple);  // only a tangency can hold the search up
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
      if (!strictly_in(p.point, search)) continue;
      int found = 0;
      for (const VertexBox& v : ours.vertices) found += in_box(p.point, v.box);
      RC_ASSERT(found == 1);
    }
}

RC_GTEST_PROP(RefinerVoronoiVertex, SignsAtVerticesAreTheExactSigns, ()) {
  const Case c = *trio_case();
  RC_PRE(distinct(c));
  const auto exact = anisocert::oracle::intersect(bisector(c.t[0], c.t[1]), bisector(c.t[0], c.t[2]));
  RC_PRE(!exact.shared_component);
  const VertexSearch ours = vertices_in(c.t, search);
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
      if (c.kind == "equal metrics") RC_ASSERT(ours_sign.has_value());  // a rational vertex decides ties too
    }
  }
}

// Signs of expressions in two points (here x₁ − x₂ of two vertices, or of a vertex and a double
// point) against the oracle's exact comparison.
RC_GTEST_PROP(RefinerVoronoiVertex, SignsAtTwoPointsAreTheExactSigns, ()) {
  const Case c = *trio_case();
  RC_PRE(distinct(c));
  const auto exact = anisocert::oracle::intersect(bisector(c.t[0], c.t[1]), bisector(c.t[0], c.t[2]));
  RC_PRE(!exact.shared_component);
  const VertexSearch ours = vertices_in(c.t, search);
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
  const Case c = *trio_case();
  RC_PRE(distinct(c));
  const auto exact = anisocert::oracle::intersect(bisector(c.t[0], c.t[1]), bisector(c.t[0], c.t[2]));
  RC_PRE(!exact.shared_component);
  for (const VertexBox& v : vertices_in(c.t, search).vertices) {
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
      const double scale = 1 + std::abs(v.approx().x) + std::abs(v.approx().y);
      RC_ASSERT(wx <= std::ldexp(scale, -400));
      RC_ASSERT(wy <= std::ldexp(scale, -400));
    }
  }
}
