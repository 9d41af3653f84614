#pragma once
// The generic refinement loop (CGAL Mesh_2's Mesher_level, flattened): one element at a time, the
// levels in priority order (the edge level, Boundary, before the refiner's own), until nothing is
// left to refine, a budget is spent, or the refiner says it cannot go on. A progress line about
// once a second.
//
// A Refinement provides
//   std::size_t vertices() const;          // sites so far
//   std::size_t queued() const;            // elements waiting (for the progress line)
//   const std::string& stalled() const;    // why it cannot go on, or empty
//   bool step();                           // refines one element; false when none is left
//   std::string done() const;              // the name of its end condition, when nothing is left
#include "refiners/common/result.hpp"

#include <chrono>
#include <functional>
#include <string>
#include <utility>

namespace anisocert::refiners::common {

using Progress = std::function<void(const std::string&)>;

class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The clock is read every this many steps (reading it costs more than a step of a small mesh).
inline constexpr std::size_t steps_per_clock_reading = 64;

// Runs r until it is done or stopped; returns the stop reason.
template <class Refinement>
std::string refine_until_done(Refinement& r, const Budget& budget, const Stopwatch& clock, const Progress& progress) {
  double next_report = 1;
  for (std::size_t steps = 1;; ++steps) {
    if (r.vertices() >= budget.max_vertices) return "vertex budget (" + std::to_string(budget.max_vertices) + ") reached";
    const bool read_clock = steps % steps_per_clock_reading == 0;
    if (read_clock && clock.seconds() > budget.max_seconds)
      return "time budget (" + std::to_string(budget.max_seconds) + " s) reached";
    if (progress && read_clock && clock.seconds() > next_report) {
      next_report += 1;
      progress("refine: " + std::to_string(r.vertices()) + " vertices, " +
               std::to_string(static_cast<long>(r.vertices() / clock.seconds())) + " per second, queue " +
               std::to_string(r.queued()));
    }
    if (!r.stalled().empty()) return r.stalled();
    if (!r.step()) return r.done();
  }
}

// A whole run: the Refinement built from `args`, run until done or stopped, its result (with the
// stop reason, whether it finished, and the time taken).
template <class Refinement, class... Args>
auto run_refinement(const Budget& budget, const Progress& progress, Args&&... args) {
  const Stopwatch clock;
  Refinement r(std::forward<Args>(args)...);
  const std::string stop = refine_until_done(r, budget, clock, progress);
  auto result = r.result(stop, stop == r.done());
  result.seconds = clock.seconds();
  return result;
}

}  // namespace anisocert::refiners::common
