// The generic refinement loop (refiners/common/refinement_loop.hpp) on refinements that only count
// their steps: the stop reasons and their order, and how far a time budget can be overrun.
#include "refiners/common/refinement_loop.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace anisocert::refiners::common;

namespace {

// n steps, each `pause` long, then done.
struct Counting {
  std::size_t n = 0, steps = 0;
  std::chrono::milliseconds pause{0};
  std::string stall;
  std::size_t vertices() const { return steps; }
  std::size_t queued() const { return n - steps; }
  const std::string& stalled() const { return stall; }
  bool step() {
    if (steps == n) return false;
    std::this_thread::sleep_for(pause);
    ++steps;
    return true;
  }
  std::string done() const { return "nothing left"; }
};

}  // namespace

TEST(RefinementLoop, NamesWhatEndedTheRun) {
  Counting r{10, 0, {}, {}};
  const Stop s = refine_until_done(r, Budget{}, Stopwatch{}, {});
  EXPECT_EQ(s.reason, "nothing left");
  EXPECT_TRUE(s.finished);
  EXPECT_FALSE(s.out_of_time);
  Counting v{100, 0, {}, {}};
  const Stop t = refine_until_done(v, Budget{40, 1e9}, Stopwatch{}, {});
  EXPECT_EQ(t.reason, "vertex budget (40) reached");
  EXPECT_FALSE(t.finished);
  EXPECT_EQ(v.steps, 40u);
  Counting w{100, 0, {}, {}};
  w.stall = "cannot go on";
  EXPECT_EQ(refine_until_done(w, Budget{}, Stopwatch{}, {}).reason, "cannot go on");
  EXPECT_EQ(w.steps, 0u);
}

// Steps of 20 ms against a budget of 0.1 s: the clock is read after every step once steps are seen
// to be slow, so the run stops one or two steps after the budget is spent (about 5 or 6 steps; a
// loaded machine, whose sleeps overshoot, only makes fewer). Reading it every 64 steps, as the
// loop once did, ran 64 steps: 1.3 s, and a 5 s budget of LS refinement running into a corner took
// 14 s.
TEST(RefinementLoop, SlowStepsOverrunTheTimeBudgetByAboutOneStep) {
  Counting r{1000, 0, {}, {}};
  r.pause = std::chrono::milliseconds(20);
  const Stop s = refine_until_done(r, Budget{1000000, 0.1}, Stopwatch{}, {});
  EXPECT_TRUE(s.out_of_time) << s.reason;
  EXPECT_FALSE(s.finished);
  EXPECT_LE(r.steps, 8u);
  EXPECT_GE(r.steps, 1u);
}
