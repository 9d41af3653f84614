#pragma once
// What a run did, insertion by insertion and rule by rule: the trace (for the properties on
// traces: LS Theorem 11 and Lemmas 12–23, BWY §4.2) and the report's counts, in the refiner's
// priority order. Rules are the refiner's numbers (its rules.hpp), named by its table.
#include "refiners/common/result.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace anisocert::refiners::common {

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

// A rule's number in the trace and its name in the report.
struct RuleName {
  int number;
  const char* name;
};

class RunRecord {
 public:
  // The refiner's rules in priority order (a rule that no run can apply need not be listed).
  explicit RunRecord(std::vector<RuleName> by_priority) : rules_(std::move(by_priority)) {}

  // A site at q by `rule`, at squared distance nearest2 from the nearest earlier site in its
  // metric; radius: the violator's circumradius in the metric (0 for splits); displacement: q's
  // distance from the exact Voronoi vertex it rounds, from above (0 for splits); for_rule: the rule
  // whose point would have encroached, for the splits made instead (0 otherwise).
  void insertion(int rule, const predicates::Point2<double>& q, double nearest2, double radius, double displacement, int for_rule) {
    trace_.push_back({rule, q.x, q.y, std::sqrt(nearest2), -1, radius, displacement, for_rule});
    ++counts_[rule];
    last_ = rule;
  }
  // r's stop, counts, last rule and trace.
  void fill(RefineResult& r, const std::string& stop_reason, bool finished) const {
    r.consistent = finished;
    r.stop_reason = stop_reason;
    for (const RuleName& rule : rules_) r.rule_counts.emplace_back(rule.name, count(rule.number));
    r.last_rule = "none";
    for (const RuleName& rule : rules_)
      if (rule.number == last_) r.last_rule = rule.name;
    r.trace = trace_;
  }

 private:
  std::size_t count(int rule) const {
    const auto it = counts_.find(rule);
    return it == counts_.end() ? 0 : it->second;
  }

  std::vector<RuleName> rules_;
  std::map<int, std::size_t> counts_;
  int last_ = 0;
  std::vector<Insertion> trace_;
};

}  // namespace anisocert::refiners::common
