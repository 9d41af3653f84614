#include "refiners/common/corner_shells.hpp"

#include "predicates/orientation.hpp"
#include "refiners/common/segment_cells.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::common {

namespace {

// p lies on the segment from c to o, strictly between its ends, exactly.
bool inside_segment(const Point2<double>& c, const Point2<double>& o, const Point2<double>& p) {
  return predicates::orientation(c, o, p) == Sign::zero && (p.x - c.x) * (o.x - c.x) + (p.y - c.y) * (o.y - c.y) > 0 &&
         (p.x - o.x) * (c.x - o.x) + (p.y - o.y) * (c.y - o.y) > 0;
}

Rational squared(const predicates::Sym2<double>& M, const Point2<double>& a, const Point2<double>& b) {
  return predicates::quadratic_form(Rational(M.m11), Rational(M.m12), Rational(M.m22), Rational(b.x) - Rational(a.x),
                                    Rational(b.y) - Rational(a.y));
}

// Vectors u and w from a vertex meet at less than 60° in M: u·w > ½|u||w| (in doubles: a choice).
bool narrow(const predicates::Sym2<double>& M, const Point2<double>& c, const Point2<double>& u, const Point2<double>& w) {
  const double ux = u.x - c.x, uy = u.y - c.y, wx = w.x - c.x, wy = w.y - c.y;
  return predicates::bilinear_form(M.m11, M.m12, M.m22, ux, uy, wx, wy) >
         0.5 * std::sqrt(predicates::quadratic_form(M, ux, uy) * predicates::quadratic_form(M, wx, wy));
}

}  // namespace

CornerShells::CornerShells(const Domain& domain, std::vector<predicates::Sym2<double>> metrics)
    : domain_(domain), metrics_(std::move(metrics)), sharp_(domain.vertices().size(), 0) {
  std::vector<std::vector<int>> ends(domain.vertices().size());
  for (std::size_t e = 0; e < domain.segment_count(); ++e) {
    const auto [a, b] = domain.segment_ends(e);
    ends[static_cast<std::size_t>(a)].push_back(b), ends[static_cast<std::size_t>(b)].push_back(a);
  }
  const auto& at = domain.vertices();
  for (std::size_t c = 0; c < ends.size(); ++c) {
    Apex apex{static_cast<int>(c), ends[c], {}};
    for (std::size_t i = 0; i < ends[c].size(); ++i)
      for (std::size_t j = i + 1; j < ends[c].size(); ++j)
        if (narrow(metrics_[c], at[c], at[static_cast<std::size_t>(ends[c][i])], at[static_cast<std::size_t>(ends[c][j])]))
          apex.narrow.push_back({ends[c][i], ends[c][j]});
    if (apex.narrow.empty()) continue;
    sharp_[c] = 1;
    apexes_.push_back(std::move(apex));
  }
  for (const Shell& sh : first()) lopping_.push_back(sh);
}

double CornerShells::distance(int c, const Point2<double>& p) const {
  const Point2<double>& q = domain_.vertices()[static_cast<std::size_t>(c)];
  return std::sqrt(predicates::quadratic_form(metrics_[static_cast<std::size_t>(c)], p.x - q.x, p.y - q.y));
}

std::optional<double> CornerShells::parameter(int a, int b, const std::vector<Point2<double>>& points) const {
  const bool sa = sharp(a), sb = sharp(b);
  if (sa == sb) return std::nullopt;
  const int c = sa ? a : b, o = sa ? b : a;
  const double L = distance(c, points[static_cast<std::size_t>(o)]);
  const double d = std::exp2(std::floor(std::log2(2 * L / 3)));  // in [L/3, 2L/3]
  if (!(d > 0 && d < L)) return std::nullopt;
  return c == a ? d / L : 1 - d / L;
}

std::vector<CornerShells::Shell> CornerShells::first() const {
  const auto& at = domain_.vertices();
  std::vector<Shell> out;
  for (const Apex& apex : apexes_) {
    double shortest = INFINITY;
    for (int o : apex.ends) shortest = std::min(shortest, distance(apex.c, at[static_cast<std::size_t>(o)]));
    const double d = std::exp2(std::floor(std::log2(shortest / 2)));
    for (int o : apex.ends)
      if (const double L = distance(apex.c, at[static_cast<std::size_t>(o)]); d > 0 && d < L) out.push_back({apex.c, o, d / L});
  }
  return out;
}

std::optional<CornerShells::Split> CornerShells::next_first_shell(const Subsegments& subsegments, const std::vector<Point2<double>>& points) {
  while (!lopping_.empty()) {
    const Shell sh = lopping_.front();
    lopping_.pop_front();
    const auto s = subsegments.find(sh.c, sh.o);
    if (!s) continue;  // split already, or no segment
    const auto [a, b] = subsegments.ends(*s);
    const auto z = coarse_split_point(points[static_cast<std::size_t>(a)], points[static_cast<std::size_t>(b)], Rational(0), Rational(1),
                                      Rational(a == sh.c ? sh.t : 1 - sh.t), slack());
    if (z) return Split{*s, *z};
  }
  return std::nullopt;
}

std::optional<Point2<double>> CornerShells::shell_point(const Subsegments& subsegments, int s, const std::vector<Point2<double>>& points) const {
  const auto [a, b] = subsegments.ends(s);
  const std::optional<double> t = parameter(a, b, points);
  if (!t) return std::nullopt;
  const auto [c0, c1] = subsegments.edge_ends(domain_, s);
  const Rational ua = edge_parameter(c0, c1, points[static_cast<std::size_t>(a)]), L = edge_parameter(c0, c1, points[static_cast<std::size_t>(b)]) - ua;
  return coarse_split_point(c0, c1, std::min(ua, ua + L), std::max(ua, ua + L), ua + Rational(*t) * L, abs(L) * slack());
}

bool CornerShells::exempt(const std::array<int, 3>& t, const std::vector<Point2<double>>& points) const {
  // Two of the sites must be split sites (sites 0 … V − 1 are X's vertices, which lie inside no
  // segment): a filter, the test below says the same.
  const auto& at = domain_.vertices();
  const int vertices = static_cast<int>(at.size());
  if (std::count_if(t.begin(), t.end(), [&](int k) { return k >= vertices; }) < 2) return false;
  const Rational within(1, 1024);
  for (const Apex& apex : apexes_) {
    const Point2<double>& pc = at[static_cast<std::size_t>(apex.c)];
    const predicates::Sym2<double>& M = metrics_[static_cast<std::size_t>(apex.c)];
    for (const auto& [u, w] : apex.narrow)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>(j)];
          if (i == j) continue;
          const Point2<double>&p = points[static_cast<std::size_t>(a)], &q = points[static_cast<std::size_t>(b)],
                               &r = points[static_cast<std::size_t>(t[static_cast<std::size_t>(3 - i - j)])];
          if (!inside_segment(pc, at[static_cast<std::size_t>(u)], p) || !inside_segment(pc, at[static_cast<std::size_t>(w)], q)) continue;
          const Rational pq = squared(M, p, q), dp = squared(M, pc, p), dq = squared(M, pc, q);
          if (pq <= squared(M, p, r) && pq <= squared(M, q, r) && abs(dp - dq) <= within * std::min(dp, dq)) return true;
        }
  }
  return false;
}

}  // namespace anisocert::refiners::common
