#include "cli/coarsen.hpp"

#include "cli/dual_trial.hpp"
#include "cli/output.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace anisocert::cli {
namespace {

using geometry::Mesh;

// A removal: site v goes; with w ≥ 0 (an edge collapse), w moves to the midpoint of vw.
struct Removal {
  int v, w;
};

// m without the removed sites (and the collapsed ones moved), judged (dual_trial.hpp), the oracle's
// named failures as sites of m.
Trial without(const Mesh<double>& m, const std::vector<Removal>& gone, const fields::MetricField& field, std::size_t& diagrams) {
  Mesh<double> rest;
  std::vector<int> index(m.sites.size(), 0), origin;
  std::vector<int> to(m.sites.size(), -1);
  for (const Removal& g : gone) {
    index[static_cast<std::size_t>(g.v)] = -1;
    if (g.w >= 0) to[static_cast<std::size_t>(g.w)] = g.v;
  }
  for (std::size_t k = 0; k < m.sites.size(); ++k)
    if (index[k] == 0) {
      index[k] = static_cast<int>(origin.size());
      origin.push_back(static_cast<int>(k));
      if (to[k] < 0) {
        rest.sites.push_back(m.sites[k]), rest.metrics.push_back(m.metrics[k]);
      } else {
        const auto& a = m.sites[k];
        const auto& b = m.sites[static_cast<std::size_t>(to[k])];
        const predicates::Point2<double> mid{a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
        rest.sites.push_back(mid), rest.metrics.push_back(field.at(mid.x, mid.y));
      }
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

Coarsened coarsen(const Mesh<double>& m, const fields::MetricField& field, bool collapse, bool quiet) {
  Coarsened c{m, 0, 0};
  const auto progress = progress_printer(quiet);
  std::vector<int> origin(m.sites.size());  // each current site's index in m
  for (std::size_t k = 0; k < origin.size(); ++k) origin[k] = static_cast<int>(k);
  // By index in m: how often a removal was put back (a vertex is tried at most `tries` times), and
  // the vertices on segments, never removed.
  constexpr int tries = 3;
  std::vector<int> refused(m.sites.size(), 0);
  std::vector<char> fixed(m.sites.size(), 0);  // on a segment: never removed nor moved
  for (const auto& [a, b] : m.segments) {
    refused[static_cast<std::size_t>(a)] = refused[static_cast<std::size_t>(b)] = tries;
    fixed[static_cast<std::size_t>(a)] = fixed[static_cast<std::size_t>(b)] = 1;
  }
  double share = edge_measures(m).unit_share;
  for (int round = 1;; ++round) {
    const Mesh<double>& cur = c.mesh;
    const auto n = neighbours(cur);
    std::vector<std::tuple<double, int, int>> candidates;  // (shortest mean length, site, its nearest neighbour)
    for (std::size_t v = 0; v < n.size(); ++v) {
      if (refused[static_cast<std::size_t>(origin[v])] >= tries || n[v].empty()) continue;
      double shortest = INFINITY, longest = 0;
      int nearest = -1;
      for (int w : n[v]) {
        const double l = mean_length(cur, static_cast<int>(v), w);
        if (l < shortest) shortest = l, nearest = w;
        longest = std::max(longest, l);
      }
      if (shortest < std::sqrt(0.5) && longest <= std::sqrt(2.0)) candidates.push_back({shortest, static_cast<int>(v), nearest});
    }
    std::sort(candidates.begin(), candidates.end());
    DisjointNeighbourhoods apart(n);
    std::vector<Removal> batch;
    for (const auto& [l, v, nearest] : candidates)
      if (collapse && !fixed[static_cast<std::size_t>(origin[static_cast<std::size_t>(nearest)])] && apart.admit({v, nearest}))
        batch.push_back({v, nearest});
      else if (apart.admit({v}))
        batch.push_back({v, -1});
    if (batch.empty()) break;
    const std::vector<Removal> tried = batch;
    std::size_t kept = 0;
    auto kept_batch = keep_certified(
        batch, n, [](const Removal& r) { return r.w >= 0 ? std::vector<int>{r.v, r.w} : std::vector<int>{r.v}; },
        [&](const std::vector<Removal>& gone) { return without(cur, gone, field, c.diagrams); },
        [&](const Trial& t) {
          const double s = edge_measures(t.mesh).unit_share;
          return s > share ? (share = s, true) : false;  // kept only when better, so `share` is the kept mesh's
        },
        [&](const Removal& r) { ++refused[static_cast<std::size_t>(origin[static_cast<std::size_t>(r.v)])]; });
    if (kept_batch) {
      kept = kept_batch->batch.size(), c.removed += kept;
      for (const Removal& r : kept_batch->batch) c.collapsed += r.w >= 0;
      std::vector<char> gone(origin.size(), 0);
      for (const Removal& r : kept_batch->batch) gone[static_cast<std::size_t>(r.v)] = 1;
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
      for (const Removal& r : tried) ++refused[static_cast<std::size_t>(origin[static_cast<std::size_t>(r.v)])];
  }
  return c;
}

}  // namespace anisocert::cli
