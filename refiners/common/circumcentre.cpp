#include "refiners/common/circumcentre.hpp"

#include "numbers/exact_double.hpp"

#include <cmath>
#include <optional>

namespace anisocert::refiners::common {

namespace {

// The value of kernel K at the translated inputs t, within its static bound, as a box.
template <class K>
FilterInterval within_bound(const std::array<double, K::arity>& t, const std::array<double, predicates::magnitude_groups>& max) {
  const double v = K::template eval<double>(t), e = predicates::error_bound<predicates::translated_error_model<K>>(max);
  return FilterInterval::widen(v - e, v + e);
}

}  // namespace

Point2<FilterInterval> circumcentre_box(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  using Nx = CircumcentrePartKernel<0>;
  using Ny = CircumcentrePartKernel<1>;
  using Det = CircumcentrePartKernel<2>;
  const std::array<double, 9> t{0, 0, b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y, M.m11, M.m12, M.m22};
  const auto max = predicates::group_maxima<Nx>(t);
  if (!predicates::in_static_range<Nx>(max)) return circumcentre_in<FilterInterval>(a, b, c, M);
  const FilterInterval det = within_bound<Det>(t, max);
  // A thin triangle's det can be tighter in FilterInterval than within the static bound.
  if (det.has_zero()) return circumcentre_in<FilterInterval>(a, b, c, M);
  return {FilterInterval(a.x) + within_bound<Nx>(t, max) / det, FilterInterval(a.y) + within_bound<Ny>(t, max) / det};
}

namespace {

// x = a.x + nx / det = (a.x det + nx) / det, and y likewise: the numerators X, Y and det when
// they are exact in doubles (no operation rounds: a grid's triangles), and their quotients,
// IEEE 754 divisions, rounded to nearest (ties to even); nothing otherwise, or when det is 0 or a
// quotient is not a normal double (nor 0).
struct DoubleQuotients {
  double X, Y, det, x, y;
};
std::optional<DoubleQuotients> double_quotients(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const CircumcentreParts<ExactDouble> d = circumcentre_parts<ExactDouble>(a, b, c, M);
  const ExactDouble X = ExactDouble(a.x) * d.det + d.nx, Y = ExactDouble(a.y) * d.det + d.ny;
  if (!X.exact() || !Y.exact() || !d.det.exact() || d.det.value() == 0) return std::nullopt;
  const auto normal = [](double v) { return v == 0 || (std::fabs(v) >= 0x1p-1021 && std::fabs(v) <= 0x1p1022); };
  // +0 for a zero quotient, as Boost's conversion gives (0 divided by a negative det is −0).
  const auto plus_zero = [](double v) { return v == 0 ? 0.0 : v; };
  const DoubleQuotients q{X.value(), Y.value(), d.det.value(), plus_zero(X.value() / d.det.value()), plus_zero(Y.value() / d.det.value())};
  if (!normal(q.x) || !normal(q.y)) return std::nullopt;
  return q;
}

}  // namespace

Point2<double> rounded_circumcentre(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  // Division rounds to nearest, ties to even, as Boost's conversion of the rational does.
  if (const auto q = double_quotients(a, b, c, M)) return {q->x, q->y};
  const CircumcentreParts<Expansion> p = circumcentre_parts<Expansion>(a, b, c, M);
  // x = a.x + nx / det = (a.x det + nx) / det.
  const auto x = rounded_quotient(Expansion(a.x) * p.det + p.nx, p.det);
  const auto y = rounded_quotient(Expansion(a.y) * p.det + p.ny, p.det);
  if (x && y) return {*x, *y};
  const Point2<Rational> e = circumcentre_in<Rational>(a, b, c, M);
  return {e.x.convert_to<double>(), e.y.convert_to<double>()};
}

Point2<Rational> exact_circumcentre(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  // A quotient x = X/det rounded is exact when x·det − X is 0, which an fma computes with one
  // rounding. A non-zero residue is a multiple of 2^(ℓx + ℓdet), ℓ the exponent of the lowest bit,
  // and ℓx + ℓdet >= e(X) − 106 (53-bit significands whose product is about X), so with
  // |X| >= 2⁻⁹⁰⁰ it is at least 2⁻¹⁰⁰⁷, a normal double: it cannot round to 0.
  if (const auto q = double_quotients(a, b, c, M)) {
    const auto exact = [&q](double x, double X) { return X == 0 ? x == 0 : std::fabs(X) >= 0x1p-900 && std::fma(x, q->det, -X) == 0; };
    if (exact(q->x, q->X) && exact(q->y, q->Y)) return {Rational(q->x), Rational(q->y)};
  }
  return circumcentre_in<Rational>(a, b, c, M);
}

}  // namespace anisocert::refiners::common
