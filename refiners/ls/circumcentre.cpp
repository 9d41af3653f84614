#include "refiners/ls/circumcentre.hpp"

namespace anisocert::refiners::ls {

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

Point2<double> rounded_circumcentre(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const CircumcentreParts<Expansion> p = circumcentre_parts<Expansion>(a, b, c, M);
  // x = a.x + nx / det = (a.x det + nx) / det.
  const auto x = rounded_quotient(Expansion(a.x) * p.det + p.nx, p.det);
  const auto y = rounded_quotient(Expansion(a.y) * p.det + p.ny, p.det);
  if (x && y) return {*x, *y};
  const Point2<Rational> e = circumcentre_in<Rational>(a, b, c, M);
  return {e.x.convert_to<double>(), e.y.convert_to<double>()};
}

}  // namespace anisocert::refiners::ls
