#pragma once
// What an LS run did, insertion by insertion and rule by rule: the trace (for the properties on
// traces, LS Theorem 11 and Lemmas 12–23) and the report's counts, in rules.hpp's priority order.
#include "refiners/ls/ls_refiner.hpp"
#include "refiners/ls/rules.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace anisocert::refiners::ls {

// From above, the Euclidean distance from q to the farthest point of the box [x0, x1] × [y0, y1]
// (the factor covers the rounding of the differences and of hypot).
inline double farthest_in_box(const predicates::Point2<double>& q, double x0, double x1, double y0, double y1) {
  return std::hypot(std::max(q.x - x0, x1 - q.x), std::max(q.y - y0, y1 - q.y)) * (1 + 0x1p-50);
}

// From above, the Euclidean distance from q to any point within k of q's own ulps (the step from
// |q| up) of it in each coordinate: how far a site rounded to q can be from the point it rounds.
inline double within_ulps(const predicates::Point2<double>& q, int k) {
  const double ux = std::nextafter(std::abs(q.x), INFINITY) - std::abs(q.x), uy = std::nextafter(std::abs(q.y), INFINITY) - std::abs(q.y);
  return farthest_in_box(q, q.x - k * ux, q.x + k * ux, q.y - k * uy, q.y + k * uy);
}

class RunRecord {
 public:
  // A site at q by `rule`, at squared distance nearest2 from the nearest earlier site in its
  // metric; radius: the violator's circumradius in the metric (0 for splits); displacement: q's
  // distance from the exact Voronoi vertex it rounds, from above (0 for splits); for_rule: the rule
  // whose point would have encroached, for rule 2's splits.
  void insertion(Rule rule, const predicates::Point2<double>& q, double nearest2, double radius, double displacement, Rule for_rule) {
    trace_.push_back({static_cast<int>(rule), q.x, q.y, std::sqrt(nearest2), -1, radius, displacement, static_cast<int>(for_rule)});
    ++counts_[static_cast<std::size_t>(rule)];
    last_ = rule;
  }
  // r's stop, counts, last rule and trace.
  void fill(LsResult& r, const std::string& stop_reason, bool finished) const {
    r.consistent = finished;
    r.stop_reason = stop_reason;
    for (Rule rule : rules_by_priority) r.rule_counts.emplace_back(rule_name(rule), counts_[static_cast<std::size_t>(rule)]);
    r.last_rule = rule_name(last_);
    r.trace = trace_;
  }

 private:
  std::array<std::size_t, rules_by_priority.size() + 1> counts_{};
  Rule last_ = Rule::none;
  std::vector<common::Insertion> trace_;
};

}  // namespace anisocert::refiners::ls
