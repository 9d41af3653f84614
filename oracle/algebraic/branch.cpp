#include "oracle/algebraic/branch.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace anisocert::oracle {

bool is_line(const Conic& G) { return G.a == 0 && G.b == 0 && G.c == 0; }

Polynomial discriminant_in_x(const Conic& G) {
  if (is_line(G)) return Polynomial();
  const Polynomial be(std::vector<Rational>{G.e, G.b});
  return be * be - 4 * G.c * Polynomial(std::vector<Rational>{G.f, G.d, G.a});
}

Conic derivative_in_y(const Conic& G) { return {0, 0, 0, G.b, 2 * G.c, G.e}; }

bool Branch::holds(const LocatedPoint& p) const {
  if (side == 0) return true;
  const Sign L = p.sign_of(derivative_in_y(curve));
  const int s = static_cast<int>(L) * (curve.c > 0 ? 1 : -1);
  return s == 0 || s == side;
}

Sign Branch::compare_point(const LocatedPoint& p) const {
  const Sign g = p.sign_of(curve);
  if (side == 0) return curve.e > 0 ? g : -g;  // G = e·(y − y_line)
  const int sc = curve.c > 0 ? 1 : -1;
  const int sg = static_cast<int>(g) * sc;  // sign of (y − y₋)(y − y₊)
  const int sl = static_cast<int>(p.sign_of(derivative_in_y(curve))) * sc;  // sign of y − (y₋ + y₊)/2
  if (sg < 0) return side > 0 ? Sign::negative : Sign::positive;  // strictly between the roots
  if (sg == 0) {  // on a root: the upper one when sl > 0, the lower one when sl < 0, both when 0
    if (sl == 0 || sl == side) return Sign::zero;
    return sl > 0 ? Sign::positive : Sign::negative;
  }
  return sl > 0 ? Sign::positive : Sign::negative;  // outside both roots
}

namespace {

// The roots of c·y² + (b·x0 + e)·y + (a·x0² + d·x0 + f) in intervals, lower then upper, when the
// discriminant is certainly positive and the two enclosures are apart (Vieta's stable form when
// the sign of the middle coefficient is known).
std::optional<std::pair<FilterInterval, FilterInterval>> interval_roots(const Conic& G, const Rational& x0) {
  const auto c = [](const Rational& q) { return FilterInterval::around(q); };
  const FilterInterval X = c(x0);
  const FilterInterval qa = c(G.c), qb = c(G.b) * X + c(G.e), qc = c(G.a) * X * X + c(G.d) * X + c(G.f);
  const FilterInterval disc = qb * qb - FilterInterval(4) * qa * qc;
  if (!(disc.lo > 0) || !std::isfinite(disc.hi)) return std::nullopt;
  const FilterInterval s = sqrt(disc);
  FilterInterval r1, r2;
  if (qb.lo >= 0 || qb.hi <= 0) {
    const FilterInterval t = qb.lo >= 0 ? FilterInterval(-0.5) * (qb + s) : FilterInterval(0.5) * (s - qb);
    r1 = t / qa, r2 = qc / t;
  } else {
    r1 = (-qb - s) / (FilterInterval(2) * qa), r2 = (s - qb) / (FilterInterval(2) * qa);
  }
  if (!std::isfinite(r1.lo) || !std::isfinite(r1.hi) || !std::isfinite(r2.lo) || !std::isfinite(r2.hi)) return std::nullopt;
  if (r1.hi < r2.lo) return std::pair{r1, r2};
  if (r2.hi < r1.lo) return std::pair{r2, r1};
  return std::nullopt;
}

}  // namespace

LocatedPoint Branch::at(const Rational& x0, const Rational& width) const {
  FilterContext& context = filter_context();
  if (side == 0) {
    ++context.counts.samples_filtered;
    return LocatedPoint::rational(x0, -(curve.d * x0 + curve.f) / curve.e);
  }
  if (!context.exact_only)
    if (const auto roots = interval_roots(curve, x0)) {
      ++context.counts.samples_filtered;
      const IntervalBox box{FilterInterval::around(x0), side > 0 ? roots->second : roots->first};
      return LocatedPoint(box, std::make_shared<const LocatedPoint::Recipe>([G = curve, x0, s = side] {
                            std::vector<AlgebraicPoint> r = AlgebraicPoint::on_conic_at(G, x0);
                            if (r.size() != 2) throw std::logic_error("Branch::at: x0 is not inside the branch's x-domain");
                            return s > 0 ? r[1] : r[0];
                          }));
    }
  ++context.counts.samples_exact;
  std::vector<AlgebraicPoint> roots = AlgebraicPoint::on_conic_at(curve, x0);
  if (roots.size() != 2) throw std::logic_error("Branch::at: x0 is not inside the branch's x-domain");
  return LocatedPoint(side > 0 ? roots[1] : roots[0], width);
}

int Branch::positive_side() const {
  if (side == 0) return curve.e > 0 ? 1 : -1;
  // Above the upper root and below the lower one G has the sign of c; between them the other.
  return (curve.c > 0 ? 1 : -1) * side;
}

}  // namespace anisocert::oracle
