#include "refiners/common/segment_quadratics.hpp"

#include "numbers/filter_interval.hpp"
#include "predicates/sqrt_sign.hpp"

#include <algorithm>
#include <array>

namespace anisocert::refiners::common {
namespace {

// a t² + b t + c, in rationals (exact) or FilterInterval (the filter).
template <class T>
struct Quadratic {
  T a, b, c;
  Quadratic operator-(const Quadratic& o) const { return {a - o.a, b - o.b, c - o.c}; }
  double at(double t) const { return (a.template convert_to<double>() * t + b.template convert_to<double>()) * t + c.template convert_to<double>(); }
};

// q_u(t) along ab.
template <class T>
Quadratic<T> along(const MetricSite& u, const Point2<double>& a, const Point2<double>& b) {
  const T dx = T(b.x) - T(a.x), dy = T(b.y) - T(a.y);
  const T ex = T(a.x) - T(u.p.x), ey = T(a.y) - T(u.p.y);
  const T m11(u.M.m11), m12(u.M.m12), m22(u.M.m22);
  const T mdx = m11 * dx + m12 * dy, mdy = m12 * dx + m22 * dy;  // M_u (b − a)
  const T mex = m11 * ex + m12 * ey, mey = m12 * ex + m22 * ey;  // M_u (a − u)
  return {dx * mdx + dy * mdy, T(2) * (ex * mdx + ey * mdy), ex * mex + ey * mey};
}

// f over [t0, t1] in the centred form about the midpoint m: f(m) + f′(m)δ + aδ², |δ| ≤ h.
FilterInterval over(const Quadratic<FilterInterval>& f, double t0, double t1) {
  const FilterInterval m = FilterInterval(t0, t1).midpoint(), delta = FilterInterval(t0, t1) - m;
  return (f.a * m + f.b) * m + f.c + (FilterInterval(2) * f.a * m + f.b) * delta + f.a * sqr(delta);
}

// reaches() in FilterInterval: false when on every piece of [0, 1] (up to 64) f₁ > 0 or f₂ > 0;
// true when both are negative at a piece's midpoint; nothing when that does not decide.
std::optional<bool> reaches_filtered(const Quadratic<FilterInterval>& f1, const Quadratic<FilterInterval>& f2) {
  constexpr int most = 64;
  std::array<std::pair<double, double>, most + 1> pieces;  // a stack: each visit pops one piece and pushes at most two
  int pending = 0;
  pieces[pending++] = {0, 1};
  for (int visited = 0; pending > 0; ++visited) {
    if (visited == most) return std::nullopt;
    const auto [t0, t1] = pieces[--pending];
    if (over(f1, t0, t1).lo > 0 || over(f2, t0, t1).lo > 0) continue;
    const double m = t0 + (t1 - t0) / 2;
    if (over(f1, m, m).hi < 0 && over(f2, m, m).hi < 0) return true;
    pieces[pending++] = {t0, m};
    pieces[pending++] = {m, t1};
  }
  return false;
}

// t = p + q√D.
struct Root {
  Rational p, q, D;
};

Sign sign_at(const Quadratic<Rational>& f, const Root& t) {
  const Rational A = f.a * (t.p * t.p + t.q * t.q * t.D) + f.b * t.p + f.c, B = (f.a * 2 * t.p + f.b) * t.q;
  return predicates::sign_of_root_sum(A, B, t.D);
}

// The real roots of f in [0, 1] (f not identically zero).
void add_roots_in_unit(const Quadratic<Rational>& f, std::vector<Root>& out) {
  if (f.a == 0) {
    if (f.b == 0) return;
    const Rational t = -f.c / f.b;
    if (t >= 0 && t <= 1) out.push_back({t, 0, 0});
    return;
  }
  const Rational D = f.b * f.b - 4 * f.a * f.c;
  if (D < 0) return;
  const Rational p = -f.b / (2 * f.a), q = Rational(1) / (2 * f.a);
  for (const Rational& s : {q, Rational(-q)})
    if (predicates::sign_of_root_sum(p, s, D) != Sign::negative && predicates::sign_of_root_sum(1 - p, -s, D) != Sign::negative)
      out.push_back({p, s, D});
}

}  // namespace

// The set {t ∈ [0, 1] : f₁(t) ≤ 0, f₂(t) ≤ 0} is a union of closed intervals; each begins at 0 or
// where f₁ or f₂ vanishes. So it is empty unless one of those points is in it.
bool reaches(const MetricSite& a, const MetricSite& b, const MetricSite& w, bool filter) {
  if (filter) {
    using FI = FilterInterval;
    const Quadratic<FI> qw = along<FI>(w, a.p, b.p);
    if (const auto decided = reaches_filtered(qw - along<FI>(a, a.p, b.p), qw - along<FI>(b, a.p, b.p))) return *decided;
  }
  const Quadratic<Rational> qw = along<Rational>(w, a.p, b.p), f1 = qw - along<Rational>(a, a.p, b.p), f2 = qw - along<Rational>(b, a.p, b.p);
  std::vector<Root> at{{0, 0, 0}, {1, 0, 0}};
  add_roots_in_unit(f1, at);
  add_roots_in_unit(f2, at);
  return std::any_of(at.begin(), at.end(), [&](const Root& t) { return sign_at(f1, t) != Sign::positive && sign_at(f2, t) != Sign::positive; });
}

double midpoint_parameter(const MetricSite& a, const MetricSite& b) {
  const Quadratic<Rational> g = along<Rational>(a, a.p, b.p) - along<Rational>(b, a.p, b.p);  // −|b − a|²_b at 0, |b − a|²_a at 1
  double lo = 0, hi = 1;
  for (int i = 0; i < 64 && lo < hi; ++i) {
    const double mid = lo + (hi - lo) / 2;
    if (mid <= lo || mid >= hi) break;
    (g.at(mid) < 0 ? lo : hi) = mid;
  }
  return lo + (hi - lo) / 2;
}

std::vector<std::pair<double, double>> nearest_ranges(const Point2<double>& a, const Point2<double>& b, const MetricSite& w,
                                                      const std::vector<MetricSite>& others) {
  const Quadratic<Rational> qw = along<Rational>(w, a, b);
  std::vector<Quadratic<Rational>> f;
  std::vector<double> cuts{0, 1};
  for (const MetricSite& u : others) {
    f.push_back(qw - along<Rational>(u, a, b));
    const double A = f.back().a.convert_to<double>(), B = f.back().b.convert_to<double>(), C = f.back().c.convert_to<double>();
    if (A == 0) {
      if (B != 0) cuts.push_back(-C / B);
    } else if (const double D = B * B - 4 * A * C; D >= 0) {
      cuts.push_back((-B + std::sqrt(D)) / (2 * A));
      cuts.push_back((-B - std::sqrt(D)) / (2 * A));
    }
  }
  std::erase_if(cuts, [](double t) { return !(t >= 0 && t <= 1); });
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::pair<double, double>> ranges;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double mid = cuts[i] + (cuts[i + 1] - cuts[i]) / 2;
    if (!std::all_of(f.begin(), f.end(), [mid](const Quadratic<Rational>& g) { return g.at(mid) <= 0; })) continue;
    if (!ranges.empty() && ranges.back().second == cuts[i]) ranges.back().second = cuts[i + 1];
    else ranges.emplace_back(cuts[i], cuts[i + 1]);
  }
  return ranges;
}

bool nearest_at(const Point2<Rational>& z, const MetricSite& w, const std::vector<MetricSite>& others) {
  const auto d2 = [&](const MetricSite& u) {
    return common::distance2(common::lift<Rational>(u, [](double x) { return Rational(x); }), z.x, z.y);
  };
  const Rational dw = d2(w);
  return std::all_of(others.begin(), others.end(), [&](const MetricSite& u) { return dw <= d2(u); });
}

}  // namespace anisocert::refiners::common
