#include "refiners/common/segment_cells.hpp"

#include "numbers/exact_double.hpp"
#include "numbers/expansion.hpp"
#include "numbers/filter_interval.hpp"
#include "refiners/common/exact_split.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace anisocert::refiners::common {

namespace {

Integer floor_of(const Rational& q) {
  Integer n = numerator(q), d = denominator(q);  // d > 0
  Integer f = n / d;                               // truncated
  if (f * d > n) f -= 1;
  return f;
}

// The sign of an exact number; nothing for a double that rounded or an expansion that overflowed
// or underflowed.
std::optional<Sign> sign_if_exact(const Rational& q) { return sign_of(q); }
template <class T>
  requires std::is_same_v<T, Expansion> || std::is_same_v<T, ExactDouble>
std::optional<Sign> sign_if_exact(const T& e) {
  if (!e.exact()) return std::nullopt;
  return e.sign();
}
Rational rational(const Rational& q) { return q; }
Rational rational(const Expansion& e) { return exact_value(e); }
Rational rational(const ExactDouble& e) { return Rational(e.value()); }

// cells_along in T (ExactDouble, Expansion or Rational), every comparison of two ends n/d (d > 0)
// made as sign(n₁d₂ − n₂d₁), so that no division is needed; nothing when a value is inexact.
// only: the cell of the site with that id alone.
template <class T>
std::optional<std::vector<CellOnSegment>> cells_in(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M,
                                                   const std::vector<std::pair<int, Point2<double>>>& sites, std::optional<int> only) {
  const T m11(M.m11), m12(M.m12), m22(M.m22);
  const auto form = [&](const T& x1, const T& y1, const T& x2, const T& y2) { return m11 * x1 * x2 + m12 * (x1 * y2 + y1 * x2) + m22 * y1 * y2; };
  const T dx = T(b.x) - T(a.x), dy = T(b.y) - T(a.y);
  struct Line {
    T alpha, beta;  // ℓ(t) = α + β t
  };
  std::vector<Line> lines;
  lines.reserve(sites.size());
  for (const auto& [id, u] : sites) {
    const T ux = T(u.x) - T(a.x), uy = T(u.y) - T(a.y);
    lines.push_back({form(ux, uy, ux, uy), T(-2) * form(dx, dy, ux, uy)});
  }
  struct End {
    T n, d;  // n/d, d > 0
  };
  const auto compare = [](const End& x, const End& y) { return sign_if_exact(x.n * y.d - y.n * x.d); };
  std::vector<CellOnSegment> cells;
  for (std::size_t u = 0; u < sites.size(); ++u) {
    if (only && sites[u].first != *only) continue;
    End lo{T(0), T(1)}, hi{T(1), T(1)};
    bool empty = false;
    for (std::size_t x = 0; x < sites.size() && !empty; ++x) {
      if (x == u) continue;
      // ℓ_u(t) <= ℓ_x(t) ⇔ (β_u − β_x) t <= α_x − α_u.
      const T slope = lines[u].beta - lines[x].beta, rhs = lines[x].alpha - lines[u].alpha;
      const auto s = sign_if_exact(slope);
      if (!s) return std::nullopt;
      if (*s == Sign::zero) {
        const auto r = sign_if_exact(rhs);
        if (!r) return std::nullopt;
        empty = *r == Sign::negative;
      } else {
        const End end = *s == Sign::positive ? End{rhs, slope} : End{-rhs, -slope};
        const auto c = compare(end, *s == Sign::positive ? hi : lo);
        if (!c) return std::nullopt;
        if (*s == Sign::positive && *c == Sign::negative) hi = end;
        if (*s == Sign::negative && *c == Sign::positive) lo = end;
      }
      if (!empty) {
        const auto order = compare(lo, hi);
        if (!order) return std::nullopt;
        empty = *order == Sign::positive;
      }
    }
    if (!empty) cells.push_back({sites[u].first, rational(lo.n) / rational(lo.d), rational(hi.n) / rational(hi.d)});
  }
  return cells;
}

}  // namespace

namespace {

std::vector<CellOnSegment> cells_of(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M,
                                    const std::vector<std::pair<int, Point2<double>>>& sites, bool expansions, std::optional<int> only) {
  if (expansions) {
    if (auto cells = cells_in<ExactDouble>(a, b, M, sites, only)) return std::move(*cells);  // a grid's rounds nowhere
    if (auto cells = cells_in<Expansion>(a, b, M, sites, only)) return std::move(*cells);
  }
  return *cells_in<Rational>(a, b, M, sites, only);
}

}  // namespace

std::vector<CellOnSegment> cells_along(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M,
                                       const std::vector<std::pair<int, Point2<double>>>& sites, bool expansions) {
  return cells_of(a, b, M, sites, expansions, std::nullopt);
}

std::optional<CellOnSegment> cell_along(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M,
                                        const std::vector<std::pair<int, Point2<double>>>& sites, int site, bool expansions) {
  auto cells = cells_of(a, b, M, sites, expansions, site);
  if (cells.empty()) return std::nullopt;
  return std::move(cells.front());
}

common::Box near_segment(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M) {
  const FilterInterval dx = FilterInterval(b.x) - a.x, dy = FilterInterval(b.y) - a.y;
  const FilterInterval length2 = predicates::quadratic_form(FilterInterval(M.m11), FilterInterval(M.m12), FilterInterval(M.m22), dx, dy);
  const FilterInterval det = FilterInterval(M.m11) * M.m22 - FilterInterval(M.m12) * M.m12, trace = FilterInterval(M.m11) + M.m22;
  const double r = sqrt(length2 * 0.25 * trace / det).hi;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!std::isfinite(r)) return {-inf, inf, -inf, inf};
  const auto down = [](double x) { return FilterInterval::next_down(x); };
  const auto up = [](double x) { return FilterInterval::next_up(x); };
  return {down(std::min(a.x, b.x) - r), up(std::max(a.x, b.x) + r), down(std::min(a.y, b.y) - r), up(std::max(a.y, b.y) + r)};
}

bool outside_diametral_ellipse(const Point2<double>& a, const Point2<double>& b, const Sym2<double>& M, const Point2<double>& p) {
  const FilterInterval m11(M.m11), m12(M.m12), m22(M.m22);
  const FilterInterval dx = FilterInterval(b.x) - a.x, dy = FilterInterval(b.y) - a.y;
  const FilterInterval ex = FilterInterval(p.x) - (FilterInterval(a.x) + b.x) * 0.5, ey = FilterInterval(p.y) - (FilterInterval(a.y) + b.y) * 0.5;
  return (predicates::quadratic_form(m11, m12, m22, ex, ey) - predicates::quadratic_form(m11, m12, m22, dx, dy) * 0.25).lo > 0;
}

namespace {

// On an axis-parallel ab (one coordinate shared, the other v running from v_a to v_b): the point
// whose v is `v` (a double), and its parameter (v − v_a)/(v_b − v_a).
struct AxisSegment {
  bool along_y;
  double va, vb;
  Point2<double> at(const Point2<double>& a, double v) const { return along_y ? Point2<double>{a.x, v} : Point2<double>{v, a.y}; }
  Rational parameter(double v) const { return (Rational(v) - Rational(va)) / (Rational(vb) - Rational(va)); }
  Rational value(const Rational& t) const { return Rational(va) + t * (Rational(vb) - Rational(va)); }
};
std::optional<AxisSegment> axis_segment(const Point2<double>& a, const Point2<double>& b) {
  if (a.x == b.x && a.y != b.y) return AxisSegment{true, a.y, b.y};
  if (a.y == b.y && a.x != b.x) return AxisSegment{false, a.x, b.x};
  return std::nullopt;
}

// The double of fewest significant bits strictly between the rationals lo < hi: the multiple of
// the largest power of two 2ᵉ that has one there, nearest `target`; nothing when none is a double.
std::optional<double> coarsest_double_between(const Rational& lo, const Rational& hi, const Rational& target) {
  const double top = std::max(std::abs(lo.convert_to<double>()), std::abs(hi.convert_to<double>()));
  if (!std::isfinite(top) || top == 0) return std::nullopt;
  for (int e = std::ilogb(top) + 1; e >= std::ilogb(top) - 53; --e) {
    const Rational step = e >= 0 ? Rational(Integer(1) << e) : Rational(Integer(1), Integer(1) << -e);
    const Rational first = Rational(-floor_of(-(lo / step)) ) * step;  // ⌈lo/2ᵉ⌉ 2ᵉ
    if (first >= hi) continue;
    const Rational nearest = std::clamp(Rational(floor_of(target / step + Rational(1, 2))) * step, first, hi);
    for (const Rational& v : {nearest, first}) {
      if (v <= lo || v >= hi) continue;
      const double d = v.convert_to<double>();
      if (Rational(d) == v) return d;
    }
  }
  return std::nullopt;
}

// The grid's point (split_point's first way).
std::optional<Point2<double>> grid_split_point(const Point2<double>& a, const Point2<double>& b, const Rational& lo, const Rational& hi,
                                               const Rational& wanted) {
  const Rational half(1, 2);
  if (wanted == half && lo <= half && half <= hi)
    if (const auto m = common::exact_midpoint(a, b)) return m;
  const int k = std::min(common::exact_halvings(a, b), 60);
  if (k < 1) return std::nullopt;
  const Integer scale = Integer(1) << k;
  const Rational target = std::clamp(wanted, lo, hi);
  // The grid points of [lo, hi] ∩ (0, 1): j from max(⌈lo 2ᵏ⌉, 1) to min(⌊hi 2ᵏ⌋, 2ᵏ − 1).
  const Integer first = std::max(Integer(-floor_of(-lo * scale)), Integer(1));
  const Integer last = std::min(floor_of(hi * scale), Integer(scale - 1));
  if (first > last) return std::nullopt;
  const Integer nearest = std::clamp(floor_of(target * scale + half), first, last);
  const Rational t(nearest, scale);
  const Rational x = Rational(a.x) + t * (Rational(b.x) - Rational(a.x)), y = Rational(a.y) + t * (Rational(b.y) - Rational(a.y));
  const Point2<double> z{x.convert_to<double>(), y.convert_to<double>()};
  if (Rational(z.x) != x || Rational(z.y) != y) return std::nullopt;  // not a double (exact_halvings is a lower bound)
  return z;
}

}  // namespace

std::optional<Point2<double>> split_point(const Point2<double>& a, const Point2<double>& b, const Rational& lo, const Rational& hi,
                                          const Rational& wanted) {
  if (const auto z = grid_split_point(a, b, lo, hi, wanted)) return z;
  const auto axis = axis_segment(a, b);
  if (!axis) return std::nullopt;
  const Rational t = std::clamp(wanted, std::max(lo, Rational(0)), std::min(hi, Rational(1)));
  const double v = axis->value(t).convert_to<double>();
  const Rational u = axis->parameter(v);
  if (u < lo || u > hi || u <= 0 || u >= 1) return std::nullopt;
  return axis->at(a, v);
}

std::optional<Point2<double>> coarse_split_point(const Point2<double>& a, const Point2<double>& b, const Rational& lo, const Rational& hi,
                                                 const Rational& target, const Rational& slack) {
  const Rational from = std::max(lo, target - slack), to = std::min(hi, target + slack);
  const int most = std::min(common::exact_halvings(a, b), 60);
  for (int k = 1; k <= most; ++k) {
    const Integer scale = Integer(1) << k;
    const Rational t(floor_of(std::clamp(target, from, to) * scale + Rational(1, 2)), scale);
    if (t <= from || t >= to || t <= 0 || t >= 1) continue;
    if (const auto z = grid_split_point(a, b, t, t, t)) return z;
  }
  const auto axis = axis_segment(a, b);
  if (!axis) return std::nullopt;
  const Rational v0 = axis->value(std::max(from, Rational(0))), v1 = axis->value(std::min(to, Rational(1)));
  const auto v = coarsest_double_between(std::min(v0, v1), std::max(v0, v1), axis->value(std::clamp(target, from, to)));
  if (!v) return std::nullopt;
  return axis->at(a, *v);
}

}  // namespace anisocert::refiners::common
