#include "oracle/algebraic/located_point.hpp"

#include "oracle/algebraic/narrowed_box.hpp"

#include <cmath>

namespace anisocert::oracle {

namespace {

FilterInterval enclosure(const RealAlgebraic& a, const Rational& width) {
  a.refine_below(width);
  return {FilterInterval::around(a.lo()).lo, FilterInterval::around(a.hi()).hi};
}

FilterCounts& counts() { return filter_context().counts; }

}  // namespace

LocatedPoint::LocatedPoint(AlgebraicPoint p, const Rational& width) : exact_(std::make_unique<AlgebraicPoint>(std::move(p))) {
  x = enclosure(exact_->x(), width);
  y = enclosure(exact_->y(), width);
}

LocatedPoint::LocatedPoint(const IntervalBox& box, std::shared_ptr<const Recipe> recipe, std::shared_ptr<const Curves> curves)
    : x(box.x), y(box.y), recipe_(std::move(recipe)), curves_(std::move(curves)) {}

LocatedPoint LocatedPoint::rational(const Rational& x, const Rational& y) {
  return LocatedPoint({FilterInterval::around(x), FilterInterval::around(y)},
                      std::make_shared<const Recipe>([x, y] { return AlgebraicPoint::rational(x, y); }));
}

LocatedPoint::LocatedPoint(const LocatedPoint& o)
    : x(o.x), y(o.y), recipe_(o.recipe_), curves_(o.curves_), exact_(o.exact_ ? std::make_unique<AlgebraicPoint>(*o.exact_) : nullptr) {}

LocatedPoint& LocatedPoint::operator=(const LocatedPoint& o) {
  if (this != &o) {
    x = o.x, y = o.y, recipe_ = o.recipe_, curves_ = o.curves_;
    exact_ = o.exact_ ? std::make_unique<AlgebraicPoint>(*o.exact_) : nullptr;
  }
  return *this;
}

LocatedPoint::~LocatedPoint() = default;

const AlgebraicPoint& LocatedPoint::exact() const {
  if (!exact_) {
    ++counts().exact_points;
    exact_ = std::make_unique<AlgebraicPoint>((*recipe_)());
  }
  return *exact_;
}

std::optional<IntervalBox> LocatedPoint::narrowed() const {
  if (!curves_) return std::nullopt;
  const auto [A, B] = (*curves_)();
  return narrowed_box(A, B, {x, y});
}

FilterInterval LocatedPoint::value(const Conic& G) const {
  auto c = [](const Rational& q) { return FilterInterval::around(q); };
  return c(G.a) * x * x + c(G.b) * x * y + c(G.c) * y * y + c(G.d) * x + c(G.e) * y + c(G.f);
}

Sign LocatedPoint::sign_of(const Conic& G) const {
  if (const auto s = value(G).sign(); s && *s != Sign::zero) {
    ++counts().signs_filtered;
    return *s;
  }
  ++counts().signs_exact;
  return exact().sign_of(G.polynomial());
}

bool LocatedPoint::apart_from(const LocatedPoint& q) const {
  return x.hi < q.x.lo || q.x.hi < x.lo || y.hi < q.y.lo || q.y.hi < y.lo;
}

bool same_point(const LocatedPoint& p, const LocatedPoint& q) {
  if (p.copy_of(q)) {
    ++counts().comparisons_filtered;
    return true;
  }
  if (p.apart_from(q)) {
    ++counts().comparisons_filtered;
    return false;
  }
  ++counts().comparisons_exact;
  return same_point(p.exact(), q.exact());
}

namespace {

// sign(p.c − q.c) for the coordinate c (box `box`, exact comparison `exact`): copies are equal,
// apart boxes are ordered, and the rest is compared exactly.
Sign compare_coordinate(const LocatedPoint& p, const LocatedPoint& q, FilterInterval LocatedPoint::*box,
                        Sign (*exact)(const AlgebraicPoint&, const AlgebraicPoint&)) {
  const FilterInterval &a = p.*box, &b = q.*box;
  if (p.copy_of(q) || a.hi < b.lo || b.hi < a.lo) {
    ++counts().comparisons_filtered;
    return p.copy_of(q) ? Sign::zero : a.hi < b.lo ? Sign::negative : Sign::positive;
  }
  ++counts().comparisons_exact;
  return exact(p.exact(), q.exact());
}

}  // namespace

Sign compare_x(const LocatedPoint& p, const LocatedPoint& q) {
  return compare_coordinate(p, q, &LocatedPoint::x, &compare_x);
}

Sign compare_y(const LocatedPoint& p, const LocatedPoint& q) {
  return compare_coordinate(p, q, &LocatedPoint::y, &compare_y);
}

Sign compare_x(const LocatedPoint& p, const Rational& x0) {
  const FilterInterval q = FilterInterval::around(x0);
  if (p.x.hi < q.lo || q.hi < p.x.lo) {
    ++counts().comparisons_filtered;
    return p.x.hi < q.lo ? Sign::negative : Sign::positive;
  }
  ++counts().comparisons_exact;
  return compare(p.exact().x(), RealAlgebraic::rational(x0));
}

namespace {

// q · 2^m
Rational scaled(const Rational& q, long m) {
  const Integer p = Integer(1) << static_cast<unsigned>(m < 0 ? -m : m);
  return m >= 0 ? q * Rational(p) : q / Rational(p);
}

// The dyadic k/2^m of least m strictly inside (lo, hi), lo < hi. It is unique: two of level m
// in an interval would put one of level m − 1 between them (of two consecutive k, one is even).
Rational simplest_dyadic(const Rational& lo, const Rational& hi) {
  if (lo < 0 && hi > 0) return 0;
  if (hi <= 0) return -simplest_dyadic(-hi, -lo);
  // 0 ≤ lo < hi. At m0, 2^m0 · (hi − lo) > 2, so an integer lies strictly inside.
  const Rational w = hi - lo;
  long m = static_cast<long>(boost::multiprecision::msb(boost::multiprecision::denominator(w))) -
           static_cast<long>(boost::multiprecision::msb(boost::multiprecision::numerator(w))) + 2;
  // The least integer above lo·2^m (lo ≥ 0: truncation is the floor).
  auto first_above = [&](long level) {
    const Rational s = scaled(lo, level);
    return Integer(boost::multiprecision::numerator(s) / boost::multiprecision::denominator(s) + 1);
  };
  auto inside = [&](long level) { return Rational(first_above(level)) < scaled(hi, level); };
  while (inside(m - 1)) --m;
  return scaled(Rational(first_above(m)), -m);
}

// The simplest dyadic strictly between two numbers a < b, given an open interval (lo, hi) that
// contains [a, b] and the exact tests "a < e" and "e < b": each candidate outside (a, b) narrows
// (lo, hi); the candidates are the simplest of shrinking intervals that all contain the answer,
// so they are no more complex than it and there are finitely many.
template <class ABelow, class BAbove>
Rational between(Rational lo, Rational hi, ABelow a_below, BAbove b_above) {
  while (true) {
    const Rational e = simplest_dyadic(lo, hi);
    if (!a_below(e)) lo = e;
    else if (!b_above(e)) hi = e;
    else return e;
  }
}

Rational lower_end(const LocatedPoint& a) {
  return std::isfinite(a.x.lo) ? Rational(a.x.lo) : a.exact().x().lo() - 1;
}
Rational upper_end(const LocatedPoint& b) {
  return std::isfinite(b.x.hi) ? Rational(b.x.hi) : b.exact().x().hi() + 1;
}

}  // namespace

Rational rational_between(const LocatedPoint& a, const LocatedPoint& b) {
  return between(lower_end(a), upper_end(b), [&](const Rational& e) { return compare_x(a, e) == Sign::negative; },
                 [&](const Rational& e) { return compare_x(b, e) == Sign::positive; });
}

Rational rational_between(const LocatedPoint& a, const Rational& x0) {
  return between(lower_end(a), x0, [&](const Rational& e) { return compare_x(a, e) == Sign::negative; },
                 [&](const Rational& e) { return e < x0; });
}

Rational rational_between(const Rational& x0, const LocatedPoint& b) {
  return between(x0, upper_end(b), [&](const Rational& e) { return x0 < e; },
                 [&](const Rational& e) { return compare_x(b, e) == Sign::positive; });
}

}  // namespace anisocert::oracle
