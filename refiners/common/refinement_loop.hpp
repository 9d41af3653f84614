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
//   R result(const Stop&);                 // what the run made (for run_refinement)
#include "refiners/common/result.hpp"

#include <algorithm>
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

// The clock is read at most every this many steps (reading it costs more than a step of a small
// mesh), and more often when steps are slow: the next reading is due after as many steps as took
// about clock_reading_seconds before, so that the time budget is overrun by about one step while
// steps take about as long as the last ones (when fast steps turn slow at once, by up to 64 of
// them, once). Every 64 steps, a run of 50 ms steps, refinement running into a corner, overran a
// 5 s budget by 9 s.
inline constexpr std::size_t steps_per_clock_reading = 64;
inline constexpr double clock_reading_seconds = 0.01;

// Why a run ended: its reason as the report says it; finished: no rule applies anywhere (not a
// budget, not a stall); out_of_time: the time budget is spent, so the result should not start
// long work (a refiner's count of what is left, say).
struct Stop {
  std::string reason;
  bool finished = false, out_of_time = false;
};

// Runs r until it is done or stopped.
template <class Refinement>
Stop refine_until_done(Refinement& r, const Budget& budget, const Stopwatch& clock, const Progress& progress) {
  double next_report = 1, last_reading = 0;
  std::size_t last_step = 1, next_reading = 1;  // the clock was last read before step last_step
  for (std::size_t steps = 1;; ++steps) {
    if (r.vertices() >= budget.max_vertices) return {"vertex budget (" + std::to_string(budget.max_vertices) + ") reached"};
    if (steps == next_reading) {
      const double now = clock.seconds();
      if (now > budget.max_seconds) return {"time budget (" + std::to_string(budget.max_seconds) + " s) reached", false, true};
      if (progress && now > next_report) {
        next_report += 1;
        progress("refine: " + std::to_string(r.vertices()) + " vertices, " + std::to_string(static_cast<long>(r.vertices() / now)) +
                 " per second, queue " + std::to_string(r.queued()));
      }
      std::size_t stride = 1;  // after the first reading, before any step: no time per step known yet
      if (steps > last_step) {
        const double per_step = (now - last_reading) / static_cast<double>(steps - last_step);
        stride = per_step * steps_per_clock_reading <= clock_reading_seconds
                     ? steps_per_clock_reading
                     : std::max<std::size_t>(1, static_cast<std::size_t>(clock_reading_seconds / per_step));
      }
      last_reading = now, last_step = steps, next_reading = steps + stride;
    }
    if (!r.stalled().empty()) return {r.stalled()};
    if (!r.step()) return {r.done(), true};
  }
}

// A whole run: the Refinement built from `args`, run until done or stopped, its result (with the
// stop reason, whether it finished, and the time taken).
template <class Refinement, class... Args>
auto run_refinement(const Budget& budget, const Progress& progress, Args&&... args) {
  const Stopwatch clock;
  Refinement r(std::forward<Args>(args)...);
  auto result = r.result(refine_until_done(r, budget, clock, progress));
  result.seconds = clock.seconds();
  return result;
}

}  // namespace anisocert::refiners::common
