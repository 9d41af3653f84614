#include "refiners/common/exact_tie.hpp"

#include "predicates/angle.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/circumcentre.hpp"

#include <algorithm>

namespace anisocert::refiners::common {
namespace {

Rational squared_length(const predicates::Sym2<double>& M, const Rational& dx, const Rational& dy) {
  return Rational(M.m11) * dx * dx + 2 * Rational(M.m12) * dx * dy + Rational(M.m22) * dy * dy;
}

}  // namespace

std::optional<ExactTie> exact_tie(const std::vector<common::MetricSite>& sites, const std::vector<int>& candidates) {
  if (candidates.size() < 4) return std::nullopt;
  const auto at = [&](int k) -> const common::MetricSite& { return sites[static_cast<std::size_t>(k)]; };
  const predicates::Sym2<double>& M = at(candidates[0]).M;
  for (int k : candidates)
    if (at(k).M != M) return std::nullopt;
  const auto &a = at(candidates[0]).p, &b = at(candidates[1]).p, &c = at(candidates[2]).p;
  if (predicates::orientation(a, b, c) == Sign::zero) return std::nullopt;
  ExactTie tie{candidates, circumcentre_in<Rational>(a, b, c, M)};
  const auto r2 = [&](int k) { return squared_length(M, Rational(at(k).p.x) - tie.c.x, Rational(at(k).p.y) - tie.c.y); };
  const Rational r = r2(candidates[0]);
  for (int k : candidates)
    if (r2(k) != r) return std::nullopt;
  // Counter-clockwise around c: by half-plane (above c, or on its right on the line), then by
  // orientation, in rationals.
  const auto upper = [&](int k) {
    const Rational dy = Rational(at(k).p.y) - tie.c.y;
    return dy > 0 || (dy == 0 && Rational(at(k).p.x) > tie.c.x);
  };
  std::sort(tie.sites.begin(), tie.sites.end(), [&](int u, int v) {
    if (upper(u) != upper(v)) return upper(u);
    const Rational ux = Rational(at(u).p.x) - tie.c.x, uy = Rational(at(u).p.y) - tie.c.y;
    const Rational vx = Rational(at(v).p.x) - tie.c.x, vy = Rational(at(v).p.y) - tie.c.y;
    return ux * vy - uy * vx > 0;
  });
  return tie;
}

bool in_closed_box(const predicates::Point2<Rational>& c, const common::Box& b) {
  return c.x >= Rational(b.x0) && c.x <= Rational(b.x1) && c.y >= Rational(b.y0) && c.y <= Rational(b.y1);
}

std::vector<std::array<int, 3>> fan(const ExactTie& tie, std::size_t apex) {
  const std::size_t k = tie.sites.size();
  std::vector<std::array<int, 3>> out;
  for (std::size_t i = 1; i + 1 < k; ++i) out.push_back({tie.sites[apex], tie.sites[(apex + i) % k], tie.sites[(apex + i + 1) % k]});
  return out;
}

std::optional<std::vector<std::array<int, 3>>> good_fan(const ExactTie& tie, const std::vector<common::MetricSite>& sites,
                                                        const std::vector<predicates::Sym2<double>>& metrics, double s2) {
  const auto point = [&](int u) -> const predicates::Point2<double>& { return sites[static_cast<std::size_t>(u)].p; };
  const auto good = [&](const std::array<int, 3>& t) {
    for (const auto& M : metrics)
      for (std::size_t j = 0; j < 3; ++j)
        if (!predicates::angle_at_least_arcsin(point(t[(j + 2) % 3]), point(t[j]), point(t[(j + 1) % 3]), M, s2)) return false;
    return true;
  };
  for (std::size_t apex = 0; apex < tie.sites.size(); ++apex) {
    auto triangles = fan(tie, apex);
    if (std::all_of(triangles.begin(), triangles.end(), good)) return triangles;
  }
  return std::nullopt;
}

}  // namespace anisocert::refiners::common
