#include "oracle/algebraic/located_point.hpp"

namespace anisocert::oracle {


namespace {

FilterInterval enclosure(const RealAlgebraic& a, const Rational& width) {
  a.refine_below(width);
  return {FilterInterval::around(a.lo()).lo, FilterInterval::around(a.hi()).hi};
}

}  // namespace

LocatedPoint::LocatedPoint(AlgebraicPoint p, const Rational& width)
    : point(std::move(p)), x(enclosure(point.x(), width)), y(enclosure(point.y(), width)) {}

LocatedPoint LocatedPoint::rational(const Rational& x, const Rational& y) {
  return LocatedPoint(AlgebraicPoint::rational(x, y), Rational(1));
}

FilterInterval LocatedPoint::value(const Conic& G) const {
  auto c = [](const Rational& q) { return FilterInterval::around(q); };
  return c(G.a) * x * x + c(G.b) * x * y + c(G.c) * y * y + c(G.d) * x + c(G.e) * y + c(G.f);
}

Sign LocatedPoint::sign_of(const Conic& G) const {
  if (const auto s = value(G).sign(); s && *s != Sign::zero) return *s;
  return point.sign_of(G.polynomial());
}

bool LocatedPoint::apart_from(const LocatedPoint& q) const {
  return x.hi < q.x.lo || q.x.hi < x.lo || y.hi < q.y.lo || q.y.hi < y.lo;
}

bool same_point(const LocatedPoint& p, const LocatedPoint& q) {
  return !p.apart_from(q) && same_point(p.point, q.point);
}

Sign compare_x(const LocatedPoint& p, const LocatedPoint& q) {
  if (p.x.hi < q.x.lo) return Sign::negative;
  if (q.x.hi < p.x.lo) return Sign::positive;
  return compare_x(p.point, q.point);
}

Sign compare_y(const LocatedPoint& p, const LocatedPoint& q) {
  if (p.y.hi < q.y.lo) return Sign::negative;
  if (q.y.hi < p.y.lo) return Sign::positive;
  return compare_y(p.point, q.point);
}

Sign compare_x(const LocatedPoint& p, const Rational& x0) {
  const FilterInterval q = FilterInterval::around(x0);
  if (p.x.hi < q.lo) return Sign::negative;
  if (q.hi < p.x.lo) return Sign::positive;
  return compare(p.point.x(), RealAlgebraic::rational(x0));
}

}  // namespace anisocert::oracle
