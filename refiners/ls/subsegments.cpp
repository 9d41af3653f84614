#include "refiners/ls/subsegments.hpp"

#include "refiners/common/exact_split.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::ls {

using predicates::Point2;

int Subsegments::add(int a, int b, int edge) {
  ends_.emplace_back(a, b);
  edge_.push_back(edge);
  queued_.push_back(false);
  const int s = static_cast<int>(ends_.size()) - 1;
  queue(s);
  return s;
}

void Subsegments::queue(int s) {
  if (queued_[static_cast<std::size_t>(s)]) return;
  queued_[static_cast<std::size_t>(s)] = true;
  queue_.push_back(s);
}

std::optional<int> Subsegments::pop() {
  if (queue_.empty()) return std::nullopt;
  const int s = queue_.front();
  queue_.pop_front();
  queued_[static_cast<std::size_t>(s)] = false;
  return s;
}

int Subsegments::split(int s, int k) {
  const auto [a, b] = ends(s);
  ends_[static_cast<std::size_t>(s)] = {a, k};
  queue(s);
  return add(k, b, edge_[static_cast<std::size_t>(s)]);
}

std::pair<Point2<double>, Point2<double>> Subsegments::edge_ends(const common::Domain& domain, int s) const {
  const auto& corners = domain.corners();
  const std::size_t e = static_cast<std::size_t>(edge_[static_cast<std::size_t>(s)]);
  return {corners[e], corners[(e + 1) % corners.size()]};
}

Rational edge_parameter(const Point2<double>& c0, const Point2<double>& c1, const Point2<double>& p) {
  // Along the coordinate in which the edge is longer (never 0: the corners differ).
  if (std::abs(c1.x - c0.x) >= std::abs(c1.y - c0.y)) return (Rational(p.x) - Rational(c0.x)) / (Rational(c1.x) - Rational(c0.x));
  return (Rational(p.y) - Rational(c0.y)) / (Rational(c1.y) - Rational(c0.y));
}

std::string Subsegments::too_fine(const common::Domain& domain, const Theorem11Conditions& t11, int s, const Point2<double>& pa,
                                  const Point2<double>& pb, const Point2<double>& z) const {
  const int e = edge_[static_cast<std::size_t>(s)];
  const auto& corners = domain.corners();
  const auto& c0 = corners[static_cast<std::size_t>(e)];
  const auto& c1 = corners[(static_cast<std::size_t>(e) + 1) % corners.size()];
  const double piece = std::min(std::hypot(z.x - pa.x, z.y - pa.y), std::hypot(pb.x - z.x, pb.y - z.y));
  if (piece >= std::ldexp(std::hypot(c1.x - c0.x, c1.y - c0.y), -common::min_halvings)) return {};
  const auto [a, b] = ends(s);
  return "a split of edge " + std::to_string(e) + " would leave a piece below 2⁻³⁰ of its length" + corner_note(domain, t11, a, b);
}

}  // namespace anisocert::refiners::ls
