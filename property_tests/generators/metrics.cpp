#include "property_tests/generators/metrics.hpp"

#include "predicates/distortion.hpp"
#include "numbers/decimal_enclosure.hpp"

namespace anisocert::gen {

Sym2<Rational> Frame::metric() const {
  return {f11 * f11 + f21 * f21, f11 * f12 + f21 * f22, f12 * f12 + f22 * f22};
}

Point2<Rational> Frame::apply(const Point2<Rational>& x) const {
  return {f11 * x.x + f12 * x.y, f21 * x.x + f22 * x.y};
}

Point2<Rational> Frame::inverse(const Point2<Rational>& u) const {
  const Rational d = det();
  return {(f22 * u.x - f12 * u.y) / d, (-f21 * u.x + f11 * u.y) / d};
}

rc::Gen<Point2<Rational>> unit_vector() {
  return rc::gen::apply(
      [](int m, int n, int flips) {
        const Rational h = m * m + n * n;
        Rational a = Rational(m * m - n * n) / h, b = Rational(2 * m * n) / h;
        if (flips & 1) std::swap(a, b);
        if (flips & 2) a = -a;
        if (flips & 4) b = -b;
        return Point2<Rational>{a, b};
      },
      rc::gen::inRange(1, 12), rc::gen::inRange(0, 12), rc::gen::inRange(0, 8));
}

rc::Gen<Point2<Rational>> point() {
  return rc::gen::apply([](Rational x, Rational y) { return Point2<Rational>{x, y}; },
                        rational_in(Rational(-10), Rational(10)), rational_in(Rational(-10), Rational(10)));
}

namespace {

Tagged tagged(const Frame& F, const std::string& kind) { return {F, F.metric(), kind}; }

// F = [a b; c d] with a, d in [1, 3] and b, c in [−1/2, 1/2]: det F >= 3/4, cond(F) <= 4.
rc::Gen<Tagged> well_conditioned() {
  auto diag = rational_in(Rational(1), Rational(3));
  auto off = rational_in(Rational(-1, 2), Rational(1, 2));
  return rc::gen::apply([](Rational a, Rational b, Rational c, Rational d) { return tagged(Frame{a, b, c, d}, "well_conditioned"); },
                        diag, off, off, diag);
}

rc::Gen<Tagged> anisotropic() {
  return rc::gen::apply(
      [](Point2<Rational> u, int e, Rational scale) {
        // F = diag(s, s·t) R, R the rotation by u: eigenvalues of M in ratio t², t = 10^e.
        const Rational t = e >= 0 ? Rational(boost::multiprecision::pow(Integer{10}, e))
                                  : Rational(1) / Rational(boost::multiprecision::pow(Integer{10}, -e));
        const Frame F{scale * u.x, -scale * u.y, scale * t * u.y, scale * t * u.x};
        return tagged(F, "anisotropic");
      },
      unit_vector(), rc::gen::inRange(-3, 4), rational_in(Rational(1, 10), Rational(10)));
}

}  // namespace

rc::Gen<Tagged> metric() { return one_of_classes<Tagged>({well_conditioned(), anisotropic()}); }

rc::Gen<std::pair<Tagged, Tagged>> nearly_equal_pair() {
  return rc::gen::apply(
      [](Tagged a, int k, std::array<int, 4> e) {
        const Rational eps = ten_to_minus(k);
        Frame G{a.F.f11 + eps * e[0], a.F.f12 + eps * e[1], a.F.f21 + eps * e[2], a.F.f22 + eps * e[3]};
        if (G.det() <= 0) G = a.F;
        return std::pair{Tagged{a.F, a.M, "nearly_equal"}, tagged(G, "nearly_equal")};
      },
      metric(), rc::gen::inRange(3, 13),
      // Not shrunk: a zero perturbation would make the pair equal under a "nearly_equal" tag.
      rc::gen::noShrink(rc::gen::suchThat(rc::gen::container<std::array<int, 4>>(rc::gen::inRange(-3, 4)),
                                          [](const std::array<int, 4>& e) { return e != std::array<int, 4>{}; })));
}

rc::Gen<std::pair<Tagged, Tagged>> metric_pair() {
  auto generic = rc::gen::apply([](Tagged a, Tagged b) { return std::pair{a, b}; }, metric(), metric());
  auto equal = rc::gen::map(metric(), [](Tagged a) {
    a.kind = "equal";
    return std::pair{a, a};
  });
  return one_of_classes<std::pair<Tagged, Tagged>>({generic, nearly_equal_pair(), equal});
}

Point2<Rational> at_distance(const Point2<Rational>& q, const Frame& F, const Rational& r, const Point2<Rational>& u) {
  const Point2<Rational> d = F.inverse({r * u.x, r * u.y});
  return {q.x + d.x, q.y + d.y};
}

Rational d2(const Sym2<Rational>& M, const Point2<Rational>& a, const Point2<Rational>& b) {
  return predicates::quadratic_form(M.m11, M.m12, M.m22, Rational(b.x - a.x), Rational(b.y - a.y));
}

anisocert::Interval tau_squared_enclosure(const Sym2<Rational>& P, const Sym2<Rational>& Q, mpfr_prec_t prec) {
  const predicates::TauSquared t = predicates::tau_squared(P, Q);
  return (anisocert::Interval(t.B, prec) + sqrt(anisocert::Interval(t.D, prec))) / anisocert::Interval(t.m, prec);
}

Rational tau2_above(const Sym2<Rational>& P, const Sym2<Rational>& Q) {
  return rational_above(tau_squared_enclosure(P, Q, 200));
}

Rational rational_above(const anisocert::Interval& x) { return parse_rational(anisocert::to_decimal(x, 30).hi); }
Rational rational_below(const anisocert::Interval& x) { return parse_rational(anisocert::to_decimal(x, 30).lo); }

std::ostream& operator<<(std::ostream& os, const Tagged& t) { return os << t.M << " (" << t.kind << ")"; }

}  // namespace anisocert::gen

namespace anisocert::predicates {
std::ostream& operator<<(std::ostream& os, const Point2<Rational>& p) {
  return os << "(" << to_exact_string(p.x) << ", " << to_exact_string(p.y) << ")";
}
std::ostream& operator<<(std::ostream& os, const Sym2<Rational>& m) {
  return os << "[" << to_exact_string(m.m11) << ", " << to_exact_string(m.m12) << ", " << to_exact_string(m.m22) << "]";
}
}  // namespace anisocert::predicates
