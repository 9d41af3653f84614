#include "cli/coarsen.hpp"

#include "cli/dual_trial.hpp"
#include "cli/output.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace anisocert::cli {
namespace {

using geometry::Mesh;

// m without the sites `gone`, judged (dual_trial.hpp), the oracle's named failures as sites of m.
Trial without(const Mesh<double>& m, const std::vector<int>& gone, std::size_t& diagrams) {
  Mesh<double> rest;
  std::vector<int> index(m.sites.size(), 0), origin;
  for (int g : gone) index[static_cast<std::size_t>(g)] = -1;
  for (std::size_t k = 0; k < m.sites.size(); ++k)
    if (index[k] == 0) {
      index[k] = static_cast<int>(origin.size());
      origin.push_back(static_cast<int>(k));
      rest.sites.push_back(m.sites[k]), rest.metrics.push_back(m.metrics[k]);
    }
  rest.domain = m.domain;
  for (const auto& [a, b] : m.segments) rest.segments.push_back({index[static_cast<std::size_t>(a)], index[static_cast<std::size_t>(b)]});
  Trial t = judged(std::move(rest), diagrams);
  std::set<int> named;
  for (int s : t.near_failures) named.insert(origin[static_cast<std::size_t>(s)]);
  t.near_failures = std::move(named);
  return t;
}

}  // namespace

Coarsened coarsen(const Mesh<double>& m, bool quiet) {
  Coarsened c{m, 0, 0};
  const auto progress = progress_printer(quiet);
  std::vector<int> origin(m.sites.size());  // each current site's index in m
  for (std::size_t k = 0; k < origin.size(); ++k) origin[k] = static_cast<int>(k);
  // By index in m: how often a removal was put back (a vertex is tried at most `tries` times), and
  // the vertices on segments, never removed.
  constexpr int tries = 3;
  std::vector<int> refused(m.sites.size(), 0);
  for (const auto& [a, b] : m.segments) refused[static_cast<std::size_t>(a)] = refused[static_cast<std::size_t>(b)] = tries;
  double share = edge_measures(m).unit_share;
  for (int round = 1;; ++round) {
    const Mesh<double>& cur = c.mesh;
    const auto n = neighbours(cur);
    std::vector<std::pair<double, int>> candidates;  // (shortest mean length, site)
    for (std::size_t v = 0; v < n.size(); ++v) {
      if (refused[static_cast<std::size_t>(origin[v])] >= tries || n[v].empty()) continue;
      double shortest = INFINITY, longest = 0;
      for (int w : n[v]) {
        const double l = mean_length(cur, static_cast<int>(v), w);
        shortest = std::min(shortest, l), longest = std::max(longest, l);
      }
      if (shortest < std::sqrt(0.5) && longest <= std::sqrt(2.0)) candidates.push_back({shortest, static_cast<int>(v)});
    }
    std::sort(candidates.begin(), candidates.end());
    std::vector<char> blocked(n.size(), 0);
    std::vector<int> batch;
    for (const auto& [l, v] : candidates) {
      if (blocked[static_cast<std::size_t>(v)]) continue;
      batch.push_back(v);
      blocked[static_cast<std::size_t>(v)] = 1;
      for (int w : n[static_cast<std::size_t>(v)]) blocked[static_cast<std::size_t>(w)] = 1;
    }
    if (batch.empty()) break;
    const std::vector<int> tried = batch;
    std::size_t kept = 0;
    auto kept_batch = keep_certified(
        batch, n, [](int v) { return v; }, [&](const std::vector<int>& gone) { return without(cur, gone, c.diagrams); },
        [&](const Trial& t) {
          const double s = edge_measures(t.mesh).unit_share;
          return s > share ? (share = s, true) : false;  // kept only when better, so `share` is the kept mesh's
        },
        [&](int v) { ++refused[static_cast<std::size_t>(origin[static_cast<std::size_t>(v)])]; });
    if (kept_batch) {
      kept = kept_batch->batch.size(), c.removed += kept;
      std::vector<char> gone(origin.size(), 0);
      for (int v : kept_batch->batch) gone[static_cast<std::size_t>(v)] = 1;
      std::vector<int> next;
      for (std::size_t k = 0; k < origin.size(); ++k)
        if (!gone[k]) next.push_back(origin[k]);
      origin = std::move(next);
      c.mesh = std::move(kept_batch->trial.mesh);
    }
    if (progress)
      progress("refine --coarsen: round " + std::to_string(round) + ": " + std::to_string(kept) + " of " + std::to_string(tried.size()) +
               " vertices removed (" + std::to_string(c.removed) + " in all, " + std::to_string(c.diagrams) + " exact diagrams)");
    if (kept == 0)  // every round removes vertices or counts a refusal of each it tried, so coarsening ends
      for (int v : tried) ++refused[static_cast<std::size_t>(origin[static_cast<std::size_t>(v)])];
  }
  return c;
}

}  // namespace anisocert::cli
