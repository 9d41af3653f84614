#pragma once
// Which path the oracle's constructions take, and how often each filter decided (issue 14): every
// decision about an algebraic point is first tried on its double-interval box and falls back to
// exact arithmetic only when the interval cannot decide (DESIGN.md: a filter may only speed up,
// never change, an answer). `exact_only` switches the filtered constructions off (the points are
// built exactly, as before the filters), for differential testing and to show exactness's cost.
//
// The context belongs to the calling thread: a computation installs one per worker thread
// (FilterScope) and adds the workers' counts together at the end, so counting needs no atomics.
#include <cstdint>

namespace anisocert::oracle {

struct FilterCounts {
  // Common points of two curves (Voronoi vertices, ∂Ω crossings, vertical tangents, wedge-line
  // meetings): isolated in intervals, or by the exact resultant.
  std::uint64_t roots_filtered = 0, roots_exact = 0;
  // Points of a branch above a rational x (sample points, ordering lines).
  std::uint64_t samples_filtered = 0, samples_exact = 0;
  // Signs of a polynomial at a point (ownership, wedges, sides of a curve).
  std::uint64_t signs_filtered = 0, signs_exact = 0;
  // Comparisons of coordinates (ordering along a bisector, around a node; equality of points).
  std::uint64_t comparisons_filtered = 0, comparisons_exact = 0;
  // Exact algebraic points actually constructed (a filtered point builds its exact form only
  // when a decision needs it).
  std::uint64_t exact_points = 0;

  FilterCounts& operator+=(const FilterCounts& o) {
    roots_filtered += o.roots_filtered, roots_exact += o.roots_exact;
    samples_filtered += o.samples_filtered, samples_exact += o.samples_exact;
    signs_filtered += o.signs_filtered, signs_exact += o.signs_exact;
    comparisons_filtered += o.comparisons_filtered, comparisons_exact += o.comparisons_exact;
    exact_points += o.exact_points;
    return *this;
  }
};

struct FilterContext {
  bool exact_only = false;
  FilterCounts counts;
};

// The calling thread's context (a default one when none is installed).
FilterContext& filter_context();

// Installs `c` as the calling thread's context for its lifetime.
class FilterScope {
 public:
  explicit FilterScope(FilterContext& c);
  ~FilterScope();
  FilterScope(const FilterScope&) = delete;
  FilterScope& operator=(const FilterScope&) = delete;

 private:
  FilterContext* previous_;
};

}  // namespace anisocert::oracle
