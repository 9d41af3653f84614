#include "oracle/algebraic/narrowed_box.hpp"

#include "geometry/krawczyk.hpp"
#include "numbers/interval.hpp"

#include <array>
#include <cmath>

namespace anisocert::oracle {
namespace {

constexpr mpfr_prec_t precision = 128;

// F = (A, B) for geometry::krawczyk, its coefficients enclosed at `precision` bits. ½∇G of
// G = a x² + b xy + c y² + d x + e y + f is (a x + (b/2) y + d/2, (b/2) x + c y + e/2): its Hessian
// part [[a, b/2], [b/2, c]] is exact in δ.
class ConicPair {
 public:
  ConicPair(const Conic& A, const Conic& B) : rows_{row(A), row(B)} {}

  std::array<Interval, 2> at(const Interval& x, const Interval& y) const { return {value(rows_[0], x, y), value(rows_[1], x, y)}; }
  std::array<Interval, 4> half_jacobian(const Interval& x, const Interval& y) const {
    return {rows_[0].a * x + rows_[0].hb * y + rows_[0].hd, rows_[0].hb * x + rows_[0].c * y + rows_[0].he,
            rows_[1].a * x + rows_[1].hb * y + rows_[1].hd, rows_[1].hb * x + rows_[1].c * y + rows_[1].he};
  }
  std::array<Interval, 4> half_jacobian(const std::array<Interval, 4>& at_m, const Interval& dx, const Interval& dy) const {
    return {at_m[0] + (rows_[0].a * dx + rows_[0].hb * dy), at_m[1] + (rows_[0].hb * dx + rows_[0].c * dy),
            at_m[2] + (rows_[1].a * dx + rows_[1].hb * dy), at_m[3] + (rows_[1].hb * dx + rows_[1].c * dy)};
  }

 private:
  struct Row {
    Interval a, hb, c, hd, he, d, e, f, b;  // hb = b/2, hd = d/2, he = e/2 (exact halvings of rationals)
  };
  static Row row(const Conic& G) {
    const auto i = [](const Rational& q) { return Interval(q, precision); };
    return {i(G.a), i(G.b / 2), i(G.c), i(G.d / 2), i(G.e / 2), i(G.d), i(G.e), i(G.f), i(G.b)};
  }
  // Horner's form (a x + b y + d) x + (c y + e) y + f.
  static Interval value(const Row& r, const Interval& x, const Interval& y) { return (r.a * x + r.b * y + r.d) * x + (r.c * y + r.e) * y + r.f; }

  std::array<Row, 2> rows_;
};

// Whether [lo, hi] holds at most five doubles.
bool few_ulps(double lo, double hi) {
  for (int k = 0; k < 4 && lo < hi; ++k) lo = std::nextafter(lo, hi);
  return lo >= hi;
}

}  // namespace

std::optional<IntervalBox> narrowed_box(const Conic& A, const Conic& B, const IntervalBox& box) {
  if (!(std::isfinite(box.x.lo) && std::isfinite(box.x.hi) && std::isfinite(box.y.lo) && std::isfinite(box.y.hi))) return std::nullopt;
  const ConicPair F(A, B);
  const Interval one(1.0, precision);
  geometry::Box2<Interval> X{Interval(box.x.lo, box.x.hi, precision), Interval(box.y.lo, box.y.hi, precision)};
  bool unique = false;
  // Each step keeps every zero of X (K(X) ∩ X); once one proves a unique zero, the boxes after it
  // hold that zero. Quadratic convergence: from 1e-13 to below 1e-30 in two or three steps.
  for (int step = 0; step < 8; ++step) {
    const auto k = geometry::krawczyk(F, X, one);
    if (k.verdict == geometry::KrawczykVerdict::no_zero) return std::nullopt;  // cannot happen for a box holding the point
    unique = unique || k.verdict == geometry::KrawczykVerdict::unique_zero;
    X = k.box;
    if (unique && few_ulps(X.x.lower_double(), X.x.upper_double()) && few_ulps(X.y.lower_double(), X.y.upper_double())) break;
  }
  if (!unique) return std::nullopt;
  return IntervalBox{{X.x.lower_double(), X.x.upper_double()}, {X.y.lower_double(), X.y.upper_double()}};
}

}  // namespace anisocert::oracle
