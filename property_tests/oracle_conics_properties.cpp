// The oracle's exact conic intersection against a second, independent exact engine (FLINT
// resultants + Calcium qqbar, second_engine/): the same shared-component verdict, the same
// points (each qqbar point is proved equal to ours: it is a root of our defining polynomial
// inside our isolating interval), the same multiplicities, order and signs of polynomials.

#include "oracle/algebraic/conic_intersection.hpp"
#include "property_tests/generators/conic_pairs.hpp"
#include "property_tests/generators/rationals.hpp"
#include "property_tests/second_engine/qqbar_conics.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>


using anisocert::Rational;
using namespace anisocert::oracle;
using anisocert::Sign;
using anisocert::sign_of;
namespace qq = anisocert::second_engine;
using anisocert::gen::combine;
using anisocert::gen::line;
using anisocert::gen::product;

namespace {

struct ConicPair {
  Conic A, B;
  std::string kind;
};

rc::Gen<Rational> small() { return rc::gen::map(rc::gen::inRange(-6, 7), [](int k) { return Rational(k, 2); }); }
rc::Gen<Conic> conic() {
  return rc::gen::apply([](Rational a, Rational b, Rational c, Rational d, Rational e, Rational f) { return Conic{a, b, c, d, e, f}; },
                        small(), small(), small(), small(), small(), small());
}

rc::Gen<std::pair<Rational, Rational>> rpoint() { return rc::gen::pair(small(), small()); }

rc::Gen<ConicPair> conic_pair() {
  using P = std::pair<Rational, Rational>;
  return rc::gen::mapcat(rc::gen::noShrink(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 5))), [](int k) -> rc::Gen<ConicPair> {
    switch (k) {
      case 0:
        return rc::gen::apply([](Conic A, Conic B) { return ConicPair{A, B, "random"}; }, conic(), conic());
      case 1:  // the pencil through four chosen points
        return rc::gen::apply(
            [](P p1, P p2, P p3, P p4, Rational l, Rational m) {
              const auto [A, B] = anisocert::gen::through_four_points(p1, p2, p3, p4, l, m);
              return ConicPair{A, B, "through four points"};
            },
            rpoint(), rpoint(), rpoint(), rpoint(), small(), small());
      case 2:  // tangent at a chosen point
        return rc::gen::apply(
            [](Conic A, P p, Rational l) {
              const auto [C, D] = anisocert::gen::tangent_at(A, p, l);
              return ConicPair{C, D, "tangent"};
            },
            conic(), rpoint(), small());
      case 3:  // a shared line
        return rc::gen::apply(
            [](P p, P q, P r, P s, P t) {
              const auto [A, B] = anisocert::gen::sharing_a_line(p, q, r, s, t);
              return ConicPair{A, B, "shared line"};
            },
            rpoint(), rpoint(), rpoint(), rpoint(), rpoint());
      default:  // line pairs meeting at one point, singular for both
        return rc::gen::apply(
            [](P o, P p, P q, P r, P s) {
              const auto [A, B] = anisocert::gen::singular_at(o, p, q, r, s);
              return ConicPair{A, B, "singular point"};
            },
            rpoint(), rpoint(), rpoint(), rpoint(), rpoint());
    }
  });
}

std::ostream& operator<<(std::ostream& os, const Conic& C) {
  return os << "(" << C.a << ", " << C.b << ", " << C.c << ", " << C.d << ", " << C.e << ", " << C.f << ")";
}
std::ostream& operator<<(std::ostream& os, const ConicPair& p) { return os << p.kind << ": " << p.A << " " << p.B; }

bool degenerate_input(const Conic& C) { return C.polynomial().is_zero(); }

}  // namespace

RC_GTEST_PROP(Oracle, ConicIntersectionAgreesWithQqbar, ()) {
  const ConicPair c = *conic_pair();
  RC_PRE(!degenerate_input(c.A) && !degenerate_input(c.B));
  RC_TAG(c.kind);
  const ConicIntersection ours = intersect(c.A, c.B);
  const qq::QIntersection theirs = qq::intersect(c.A, c.B);
  RC_ASSERT(ours.shared_component == theirs.shared_component);
  RC_ASSERT(ours.points.size() == theirs.points.size());
  RC_TAG(std::to_string(ours.points.size()) + " points");
  for (std::size_t k = 0; k < ours.points.size(); ++k) {
    const AlgebraicPoint& p = ours.points[k].point;
    RC_ASSERT(qq::equals(theirs.points[k].x, p.x()));
    RC_ASSERT(qq::equals(theirs.points[k].y, p.y()));
    RC_ASSERT(ours.points[k].multiplicity == theirs.points[k].multiplicity);
    if (ours.points[k].multiplicity > 1) RC_TAG("multiple point");
    // Signs of the conics themselves (zero), of their sum, and of random quadratics.
    RC_ASSERT(p.sign_of(c.A.polynomial()) == Sign::zero);
    const Conic f = *conic();
    RC_ASSERT(static_cast<int>(p.sign_of(f.polynomial())) == qq::sign_at(f.polynomial(), theirs.points[k]));
    Bivariate g;  // x − y + r: vanishes at some points of the "through four points" class
    g.add(1, 0, 1).add(0, 1, -1).add(0, 0, *small());
    RC_ASSERT(static_cast<int>(p.sign_of(g)) == qq::sign_at(g, theirs.points[k]));
    for (std::size_t j = 0; j < ours.points.size(); ++j) {
      RC_ASSERT(static_cast<int>(compare_x(p, ours.points[j].point)) == qq::compare_x(theirs.points[k], theirs.points[j]));
      RC_ASSERT(static_cast<int>(compare_y(p, ours.points[j].point)) == qq::compare_y(theirs.points[k], theirs.points[j]));
    }
  }
}

// The same vertex reached from different pairs: three members of one pencil through four
// chosen points meet pairwise in the same points, decided equal exactly (and unequal to the
// others) across pairs.
RC_GTEST_PROP(Oracle, SameVertexFromDifferentPairsIsEqual, ()) {
  using P = std::pair<Rational, Rational>;
  const auto wide = [] { return *rc::gen::pair(anisocert::gen::rational_in(-5, 5), anisocert::gen::rational_in(-5, 5)); };
  const P p1 = wide(), p2 = wide(), p3 = wide(), p4 = wide();
  const Rational l = *anisocert::gen::rational_in(-3, 3), m = *anisocert::gen::rational_in(-3, 3),
                 n = *anisocert::gen::rational_in(-3, 3);
  RC_PRE(l != m && m != n && l != n);
  const Conic Q1 = product(line(p1, p2), line(p3, p4)), Q2 = product(line(p1, p3), line(p2, p4));
  const Conic A = combine(Q1, l, Q2), B = combine(Q1, m, Q2), C = combine(Q1, n, Q2);
  RC_PRE(!degenerate_input(A) && !degenerate_input(B) && !degenerate_input(C));
  const ConicIntersection ab = intersect(A, B), ac = intersect(A, C);
  RC_PRE(!ab.shared_component && !ac.shared_component);
  RC_ASSERT(ab.points.size() == ac.points.size());
  RC_TAG(std::to_string(ab.points.size()) + " points");
  for (std::size_t i = 0; i < ab.points.size(); ++i)
    for (std::size_t j = 0; j < ac.points.size(); ++j)
      RC_ASSERT(same_point(ab.points[i].point, ac.points[j].point) == (i == j));
}
