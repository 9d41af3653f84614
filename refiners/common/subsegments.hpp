#pragma once
// LS §9's constrained subsegments: the PSLG's segments (Ω's edges, then its interior segments;
// domain.hpp) as the refinement splits them, each with the segment it lies on, and the queue of
// those to test for encroachment (rule 1). Both LS refinements (one metric on Del_M, different
// metrics on the true diagram) and the BWY refiner keep them here.
#include "refiners/common/domain.hpp"

#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace anisocert::refiners::common {

// A refiner's note for a stop near X's vertices a … b: what its theorem asks at that corner (LS's:
// ls/theorem11_conditions.hpp's corner_note).
using CornerNote = std::function<std::string(int a, int b)>;

class Subsegments {
 public:
  // Adds the subsegment from site a to site b, a piece of X's segment `edge` (domain.hpp), and
  // queues it; its index.
  int add(int a, int b, int edge);
  // Queues s for the encroachment test unless it is queued.
  void queue(int s);
  // The next subsegment to test, taken off the queue.
  std::optional<int> pop();
  // Splits s = ab at site k: s becomes ak and kb is added; both are queued. The index of kb.
  int split(int s, int k);

  // The subsegment with ends a and b (either order), if any.
  std::optional<int> find(int a, int b) const;

  std::size_t size() const { return ends_.size(); }
  std::size_t queued() const { return queue_.size(); }
  const std::pair<int, int>& ends(int s) const { return ends_[static_cast<std::size_t>(s)]; }
  const std::vector<std::pair<int, int>>& all() const { return ends_; }
  // Whether s is a piece of Ω's boundary (not of an interior segment).
  bool on_boundary(const common::Domain& domain, int s) const { return static_cast<std::size_t>(edge_[static_cast<std::size_t>(s)]) < domain.size(); }
  // The vertices of X that the segment of s runs between.
  std::pair<predicates::Point2<double>, predicates::Point2<double>> edge_ends(const common::Domain& domain, int s) const;

  // Why subsegment s from pa to pb must not be split at z, or empty: a piece would be below 2⁻³⁰ of
  // its edge. Splits that run into a corner (LS Theorem 11's separation failing there) would go on
  // down to the resolution of doubles; no run within its budgets splits an edge 2³⁰ times.
  // note(a, b): what the stop says of the corner it runs into (corner_note).
  std::string too_fine(const common::Domain& domain, const CornerNote& note, int s, const predicates::Point2<double>& pa,
                       const predicates::Point2<double>& pb, const predicates::Point2<double>& z) const;

 private:
  std::vector<std::pair<int, int>> ends_;
  std::vector<int> edge_;  // the segment of X each lies on
  std::map<std::pair<int, int>, int> by_ends_;  // (lower end, higher end) → subsegment
  std::vector<bool> queued_;
  std::deque<int> queue_;
};

// The parameter u of the point p of the segment c0c1, p = c0 + u(c1 − c0), exactly (p must lie on it).
Rational edge_parameter(const predicates::Point2<double>& c0, const predicates::Point2<double>& c1, const predicates::Point2<double>& p);

}  // namespace anisocert::refiners::common
