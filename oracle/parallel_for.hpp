#pragma once
// Independent pieces of work on every core (issue 14): the diagram's candidate triples and pairs,
// the certifier's triangles. body(i) runs for every i in [0, n), on `threads` threads taking
// indices in small chunks; each thread decides with its own filter context (the caller's
// `exact_only`), and the counts are added to the caller's at the end. Results go to slots indexed
// by i, so the caller combines them in index order and the output does not depend on the number
// of threads. An exception stops the work, and the one of the least index is rethrown, as a loop
// would have thrown it. parallel_in_order() merges results in order a block at a time;
// concurrently() runs two different pieces of work side by side.
#include "oracle/algebraic/filter_context.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace anisocert::oracle {

// The number of threads for a request of `threads` (0: one per core).
inline int thread_count(int threads) {
  return threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// `progress(done)` is called now and then, never by two threads at once.
template <class Body>
void parallel_for(std::size_t n, int threads, Body body, const std::function<void(std::size_t)>& progress = {}) {
  FilterContext& caller = filter_context();
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> stop{false};
  std::mutex lock;  // guards the fields below and progress()
  std::size_t failed_at = n;
  std::exception_ptr failure;
  constexpr std::size_t chunk = 16;
  auto work = [&](FilterContext& context) {
    FilterScope scope(context);
    while (!stop) {
      const std::size_t begin = next.fetch_add(chunk);
      if (begin >= n) return;
      const std::size_t end = std::min(n, begin + chunk);
      for (std::size_t i = begin; i < end; ++i) {
        try {
          body(i);
        } catch (...) {
          const std::lock_guard<std::mutex> g(lock);
          if (i < failed_at) failed_at = i, failure = std::current_exception();
          stop = true;
          return;
        }
      }
      const std::size_t now = done.fetch_add(end - begin) + (end - begin);
      if (progress && now / 500 != (now - (end - begin)) / 500) {
        const std::lock_guard<std::mutex> g(lock);
        progress(now);
      }
    }
  };
  const int t = std::max(1, std::min<int>(threads, static_cast<int>((n + chunk - 1) / chunk)));
  std::vector<FilterContext> contexts(static_cast<std::size_t>(t));
  for (FilterContext& c : contexts) c.exact_only = caller.exact_only;
  std::vector<std::thread> pool;
  for (int k = 1; k < t; ++k) pool.emplace_back(work, std::ref(contexts[static_cast<std::size_t>(k)]));
  work(contexts[0]);
  for (std::thread& th : pool) th.join();
  for (const FilterContext& c : contexts) caller.counts += c.counts;
  if (failure) std::rethrow_exception(failure);
}

// compute(i) for every i in [0, n) on `threads` threads (parallel_for), and merge(i, result) on
// this thread in index order: the output does not depend on the number of threads. A block of
// indices at a time, so that the results held are one block's, not n's.
template <class Compute, class Merge>
void parallel_in_order(std::size_t n, int threads, Compute compute, Merge merge, std::size_t block = std::size_t{1} << 15) {
  std::vector<decltype(compute(std::size_t{0}))> results(std::min(n, block));
  for (std::size_t begin = 0; begin < n; begin += block) {
    const std::size_t size = std::min(block, n - begin);
    parallel_for(size, threads, [&](std::size_t i) { results[i] = compute(begin + i); });
    for (std::size_t i = 0; i < size; ++i) merge(begin + i, results[i]);
  }
}

// beside() on a thread of its own while main() runs on this one (which may itself use
// parallel_for), when `threads` > 1; one after the other otherwise. The two must write apart.
// The helper decides with its own filter context, its counts added to the caller's; an exception
// of either is rethrown after both have finished (beside's first, as one after the other would).
template <class Beside, class Main>
void concurrently(int threads, Beside beside, Main main) {
  if (threads <= 1) {
    beside();
    main();
    return;
  }
  FilterContext& caller = filter_context();
  FilterContext helper;
  helper.exact_only = caller.exact_only;
  std::exception_ptr failure;
  std::thread side([&] {
    FilterScope scope(helper);
    try {
      beside();
    } catch (...) {
      failure = std::current_exception();
    }
  });
  std::exception_ptr main_failure;
  try {
    main();
  } catch (...) {
    main_failure = std::current_exception();
  }
  side.join();
  caller.counts += helper.counts;
  if (failure) std::rethrow_exception(failure);
  if (main_failure) std::rethrow_exception(main_failure);
}

}  // namespace anisocert::oracle
