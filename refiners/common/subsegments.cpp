#include "refiners/common/subsegments.hpp"

#include "refiners/common/exact_split.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::common {

using predicates::Point2;

int Subsegments::add(int a, int b, int edge) {
  ends_.emplace_back(a, b);
  edge_.push_back(edge);
  queued_.push_back(false);
  const int s = static_cast<int>(ends_.size()) - 1;
  by_ends_[std::minmax(a, b)] = s;
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
  by_ends_.erase(std::minmax(a, b));
  by_ends_[std::minmax(a, k)] = s;
  queue(s);
  return add(k, b, edge_[static_cast<std::size_t>(s)]);
}

std::optional<int> Subsegments::find(int a, int b) const {
  const auto it = by_ends_.find(std::minmax(a, b));
  if (it == by_ends_.end()) return std::nullopt;
  return it->second;
}

std::pair<Point2<double>, Point2<double>> Subsegments::edge_ends(const common::Domain& domain, int s) const {
  const auto [a, b] = domain.segment_ends(static_cast<std::size_t>(edge_[static_cast<std::size_t>(s)]));
  return {domain.vertices()[static_cast<std::size_t>(a)], domain.vertices()[static_cast<std::size_t>(b)]};
}

Rational edge_parameter(const Point2<double>& c0, const Point2<double>& c1, const Point2<double>& p) {
  // Along the coordinate in which the edge is longer (never 0: the corners differ).
  if (std::abs(c1.x - c0.x) >= std::abs(c1.y - c0.y)) return (Rational(p.x) - Rational(c0.x)) / (Rational(c1.x) - Rational(c0.x));
  return (Rational(p.y) - Rational(c0.y)) / (Rational(c1.y) - Rational(c0.y));
}

std::string Subsegments::too_fine(const common::Domain& domain, const CornerNote& corner_note, int s, const Point2<double>& pa,
                                  const Point2<double>& pb, const Point2<double>& z) const {
  const int e = edge_[static_cast<std::size_t>(s)];
  const auto [c0, c1] = edge_ends(domain, s);
  const double piece = std::min(std::hypot(z.x - pa.x, z.y - pa.y), std::hypot(pb.x - z.x, pb.y - z.y));
  if (piece >= std::ldexp(std::hypot(c1.x - c0.x, c1.y - c0.y), -common::min_halvings)) return {};
  const auto [a, b] = ends(s);
  const std::size_t n = domain.size();
  const std::string what = static_cast<std::size_t>(e) < n ? "edge " + std::to_string(e) : "interior segment " + std::to_string(static_cast<std::size_t>(e) - n);
  // The corner refinement runs into: an end of the subsegment, or else the edge's end nearer z
  // (pieces shrink towards it from a few subsegments away).
  std::string note = corner_note(a, b);
  if (note.empty()) {
    const auto [k0, k1] = domain.segment_ends(static_cast<std::size_t>(e));
    const int k = std::hypot(z.x - c0.x, z.y - c0.y) <= std::hypot(z.x - c1.x, z.y - c1.y) ? k0 : k1;
    note = corner_note(k, k);
  }
  return "a split of " + what + " would leave a piece below 2⁻³⁰ of its length" + note;
}

}  // namespace anisocert::refiners::common
