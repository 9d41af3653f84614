#include "refiners/common/corner_shells.hpp"

#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::common {

namespace {

// p lies on the closed edge from c to u, exactly.
bool on_edge(const Point2<double>& c, const Point2<double>& u, const Point2<double>& p) {
  return predicates::orientation(c, u, p) == Sign::zero && std::min(c.x, u.x) <= p.x && p.x <= std::max(c.x, u.x) &&
         std::min(c.y, u.y) <= p.y && p.y <= std::max(c.y, u.y);
}

Rational squared(const predicates::Sym2<double>& M, const Point2<double>& a, const Point2<double>& b) {
  return predicates::quadratic_form(Rational(M.m11), Rational(M.m12), Rational(M.m22), Rational(b.x) - Rational(a.x),
                                    Rational(b.y) - Rational(a.y));
}

}  // namespace

CornerShells::CornerShells(const Domain& domain, std::vector<predicates::Sym2<double>> metrics)
    : domain_(domain), metrics_(std::move(metrics)), sharp_(domain.size(), 0) {
  const int n = static_cast<int>(domain.size());
  const auto& corners = domain.corners();
  for (int k = 0; k < n; ++k) {
    const Point2<double>&p = corners[static_cast<std::size_t>(k)], &u = corners[static_cast<std::size_t>((k + n - 1) % n)],
                         &w = corners[static_cast<std::size_t>((k + 1) % n)];
    const predicates::Sym2<double>& M = metrics_[static_cast<std::size_t>(k)];
    const double ux = u.x - p.x, uy = u.y - p.y, wx = w.x - p.x, wy = w.y - p.y;
    sharp_[static_cast<std::size_t>(k)] = predicates::bilinear_form(M.m11, M.m12, M.m22, ux, uy, wx, wy) >
                                          0.5 * std::sqrt(predicates::quadratic_form(M, ux, uy) * predicates::quadratic_form(M, wx, wy));
    if (sharp_[static_cast<std::size_t>(k)]) sharp_list_.push_back(k);
  }
}

double CornerShells::distance(int c, const Point2<double>& p) const {
  const Point2<double>& q = domain_.corners()[static_cast<std::size_t>(c)];
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
  const int n = static_cast<int>(domain_.size());
  std::vector<Shell> out;
  for (int c : sharp_list_) {
    const int u = (c + n - 1) % n, w = (c + 1) % n;
    const auto& corners = domain_.corners();
    const double Lu = distance(c, corners[static_cast<std::size_t>(u)]), Lw = distance(c, corners[static_cast<std::size_t>(w)]);
    const double d = std::exp2(std::floor(std::log2(std::min(Lu, Lw) / 2)));
    for (const auto& [o, L] : {std::pair<int, double>{w, Lw}, std::pair<int, double>{u, Lu}})
      if (d > 0 && d < L) out.push_back({c, o, d / L});
  }
  return out;
}

bool CornerShells::exempt(const std::array<int, 3>& t, const std::vector<Point2<double>>& points) const {
  const int n = static_cast<int>(domain_.size());
  const auto& corners = domain_.corners();
  const auto at = [&](int k) -> const Point2<double>& { return points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])]; };
  for (int c : sharp_list_) {
    const Point2<double>&pc = corners[static_cast<std::size_t>(c)], &pu = corners[static_cast<std::size_t>((c + n - 1) % n)],
                         &pw = corners[static_cast<std::size_t>((c + 1) % n)];
    const predicates::Sym2<double>& M = metrics_[static_cast<std::size_t>(c)];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j || t[static_cast<std::size_t>(i)] == c || t[static_cast<std::size_t>(j)] == c) continue;
        const Point2<double>&p = at(i), &q = at(j), &r = at(3 - i - j);
        if (!on_edge(pc, pu, p) || !on_edge(pc, pw, q)) continue;
        const Rational pq = squared(M, p, q), dp = squared(M, pc, p), dq = squared(M, pc, q);
        if (pq <= squared(M, p, r) && pq <= squared(M, q, r) && dp <= 2 * dq && dq <= 2 * dp) return true;
      }
  }
  return false;
}

}  // namespace anisocert::refiners::common
