#include "refiners/common/boundary.hpp"

#include "geometry/ellipse_box.hpp"
#include "predicates/encroachment.hpp"
#include "predicates/metric_dot.hpp"
#include "refiners/common/exact_split.hpp"
#include "refiners/common/segment_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::refiners::common {

Boundary::Boundary(const Domain& domain, Sites& sites) : domain_(domain), sites_(sites) {
  const int m = static_cast<int>(domain.size());
  boxes_.reset(sites_.grid);
  for (int i = 0; i < m; ++i) segments_.push_back({i, (i + 1) % m});
  for (int i = 0; i < m; ++i) set_box(i);
  neighbours_.resize(sites_.size(), {-1, -1});
  for (int i = 0; i < m; ++i) neighbours_[i] = {(i + m - 1) % m, (i + 1) % m};
  for (int s = 0; s < m; ++s) queue_.push_back(s);
}

bool Boundary::encroaches(const Point2<double>& x, const Sym2<double>& Mx, int s) const {
  if (!boxes_.box(s).contains(x)) return false;
  const auto [a, b] = segments_[s];
  for (const Sym2<double>* M : std::array<const Sym2<double>*, 3>{&Mx, &sites_.metrics[a], &sites_.metrics[b]})
    if (predicates::encroaches(x, sites_.points[a], sites_.points[b], *M)) return true;
  return false;
}

bool Boundary::encroached_by_site(int p, int s) const {
  const auto [a, b] = segments_[s];
  if (p == a || p == b) return false;
  return encroaches(sites_.points[p], sites_.metrics[p], s);
}

void Boundary::site_added() {
  for (int h : pending_) set_box(h);
  pending_.clear();
  neighbours_.resize(std::max(neighbours_.size(), sites_.size()), {-1, -1});  // begin_split may have set it
}

void Boundary::queue_encroached_by(int k) {
  for (int s : boxes_.filed_at(sites_.points[k], sites_.grid))
    if (encroached_by_site(k, s)) queue_.push_back(s);
}

void Boundary::refile() { boxes_.refile(sites_.grid); }

void Boundary::set_box(int s) {
  const auto [a, b] = segments_[s];
  const Point2<double>&pa = sites_.points[a], &pb = sites_.points[b];
  const double mx = (pa.x + pb.x) / 2, my = (pa.y + pb.y) / 2;
  double hx = 0, hy = 0;
  for (int w : {a, b}) {
    const Sym2<double>& M = sites_.metrics[w];
    const auto h = geometry::ellipse_half_widths(M, predicates::quadratic_form(M, pb.x - pa.x, pb.y - pa.y) / 4);
    hx = std::max(hx, h.hx), hy = std::max(hy, h.hy);
  }
  boxes_.set(s, {mx - 2 * hx, mx + 2 * hx, my - 2 * hy, my + 2 * hy}, sites_.grid);
}

Box Boundary::search_box(int s) const {
  const auto [a, b] = segments_[s];
  const Point2<double>&pa = sites_.points[a], &pb = sites_.points[b];
  const double mx = (pa.x + pb.x) / 2, my = (pa.y + pb.y) / 2;
  const double half = std::max(std::abs(pb.x - pa.x), std::abs(pb.y - pa.y));
  return {mx - half, mx + half, my - half, my + half};
}

std::optional<int> Boundary::next_encroached() {
  while (!queue_.empty()) {
    const int s = queue_.front();
    queue_.pop_front();
    bool still = false;
    for (int p : sites_.in(search_box(s))) still = still || encroached_by_site(p, s);
    if (still) return s;
  }
  return std::nullopt;
}

std::variant<Point2<double>, std::string> Boundary::begin_split(int s) {
  const auto [a, b] = segments_[s];
  const std::optional<Point2<double>> at = split_point(sites_.points[a], sites_.points[b], Rational(0), Rational(1));
  if (!at) {
    // The domain allows at least `min_halvings` splits of every edge (Domain), so encroachment
    // does not end at a corner: name it, and say whether Lemma 4.1 explains it.
    const auto& corners = domain_.corners();
    const Point2<double>& pa = sites_.points[a];
    std::size_t k = 0;
    for (std::size_t i = 1; i < corners.size(); ++i)
      if (std::hypot(corners[i].x - pa.x, corners[i].y - pa.y) < std::hypot(corners[k].x - pa.x, corners[k].y - pa.y)) k = i;
    return "boundary segments near " + domain_.corner_text(k) + " were split until they hold no double to split at: " +
           (!corner_is_obtuse(k)
                ? "encroachment does not end at a corner whose angle is not obtuse in the metric (LU Lemma 4.1 needs > 90°)"
                : "refinement does not end there although LU Lemma 4.1 holds at that corner (a refiner failure)");
  }
  const int k = static_cast<int>(sites_.size());
  segments_[s] = {a, k};
  segments_.push_back({k, b});
  pending_ = {s, static_cast<int>(segments_.size()) - 1};  // their boxes are set once k's metric exists
  neighbours_.resize(k + 1, {-1, -1});
  neighbours_[k] = {a, b};  // before the site is inserted, whose star needs them
  for (int e : {0, 1}) {
    if (neighbours_[a][e] == b) neighbours_[a][e] = k;
    if (neighbours_[b][e] == a) neighbours_[b][e] = k;
  }
  return *at;
}

void Boundary::end_split(int s) {
  for (int h : {s, static_cast<int>(segments_.size()) - 1})
    for (int p : sites_.in(search_box(h)))
      if (encroached_by_site(p, h)) {
        queue_.push_back(h);
        break;
      }
}

std::optional<int> Boundary::snap(const Point2<double>& x, const Sym2<double>& M, const Sym2<double>& Mx,
                                  const Point2<double>& g) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const bool outside = !domain_.contains(x);
  std::vector<int> all;
  if (outside) {
    all.resize(segments_.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  }
  int nearest = -1;
  double best = inf;
  for (int s : outside ? all : boxes_.filed_at(x, sites_.grid)) {
    const auto [a, b] = segments_[s];
    const Point2<double>&pa = sites_.points[a], &pb = sites_.points[b];
    if (predicates::encroaches(x, pa, pb, M) || encroaches(x, Mx, s)) return s;
    // How far x is from encroaching s in M, for the fall-back choice below (floating point).
    const double half = predicates::quadratic_form(M, pb.x - pa.x, pb.y - pa.y) / 4;
    const double d = predicates::quadratic_form(M, (pa.x + pb.x) / 2 - x.x, (pa.y + pb.y) / 2 - x.y);
    if (d - half < best) best = d - half, nearest = s;
  }
  if (!outside) return std::nullopt;
  // x lies beyond ∂Ω: split the subsegment between the triangle and it (Ruppert's rule: the
  // segment from the triangle's centroid to x meets it); the nearest to the centroid if several.
  int crossed = -1;
  double closest = inf;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const Point2<double>&a = sites_.points[segments_[s].first], &b = sites_.points[segments_[s].second];
    if (geometry::segments_meet(g, x, a, b) == geometry::Meeting::none) continue;
    const double d = std::hypot((a.x + b.x) / 2 - g.x, (a.y + b.y) / 2 - g.y);
    if (d < closest) closest = d, crossed = static_cast<int>(s);
  }
  return crossed >= 0 ? crossed : nearest;
}

bool Boundary::corner_is_obtuse(std::size_t k) const {
  const auto& c = domain_.corners();
  const std::size_t m = c.size();
  return predicates::metric_dot_sign(c[(k + m - 1) % m], c[k], c[(k + 1) % m], sites_.metrics[k]) == Sign::negative;
}

}  // namespace anisocert::refiners::common
