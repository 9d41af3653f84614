#include "cli/relocate.hpp"

#include "cli/dual_trial.hpp"
#include "cli/output.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace anisocert::cli {
namespace {

using geometry::Mesh;
using Point = predicates::Point2<double>;

struct Move {
  int site;
  Point to;
  predicates::Sym2<double> metric;
};

// Strictly inside one of the triangles `star` (indices into m.triangles).
bool inside_star(const Mesh<double>& m, const std::vector<std::size_t>& star, const Point& p) {
  const auto& s = m.sites;
  for (std::size_t k : star) {
    const auto& t = m.triangles[k];
    const Point &a = s[static_cast<std::size_t>(t[0])], &b = s[static_cast<std::size_t>(t[1])], &c = s[static_cast<std::size_t>(t[2])];
    const Sign o = predicates::orientation(a, b, c);
    if (o != Sign::zero && predicates::orientation(a, b, p) == o && predicates::orientation(b, c, p) == o && predicates::orientation(c, a, p) == o)
      return true;
  }
  return false;
}

// v's own edges with v at its place in m: how many are unit, and Σ (log ℓ)², ℓ each edge's
// geometric-mean length (the energy a move lowers when it keeps the count).
struct Score {
  int unit = 0;
  double energy = 0;
  bool beats(const Score& o) const { return unit > o.unit || (unit == o.unit && energy < 0.9 * o.energy); }
};

Score score_at(const Mesh<double>& m, int v, const std::set<int>& around) {
  Score s;
  for (int w : around) {
    s.unit += unit_edge(m, v, w);
    const double l = std::log(mean_length(m, v, w));
    s.energy += l * l;
  }
  return s;
}

// The move proposed for v (relocate.hpp), with its gain over staying (unit edges gained, Σ (log ℓ)²
// lost); none when no step beats staying.
std::optional<std::pair<Score, Move>> proposal(Mesh<double>& m, int v, const std::set<int>& around, const std::vector<std::size_t>& star,
                                               const fields::MetricField& field) {
  const auto vi = static_cast<std::size_t>(v);
  const Point from = m.sites[vi];
  double x = 0, y = 0;
  for (int w : around) {
    const Point& q = m.sites[static_cast<std::size_t>(w)];
    const double l = mean_length(m, v, w);
    x += q.x + (from.x - q.x) / l, y += q.y + (from.y - q.y) / l;
  }
  x /= double(around.size()), y /= double(around.size());
  const Score stay = score_at(m, v, around);
  const auto metric = m.metrics[vi];
  std::optional<std::pair<Score, Move>> best;
  for (double step : {1.0, 0.5, 0.25}) {
    const Point to{from.x + step * (x - from.x), from.y + step * (y - from.y)};
    if ((to.x == from.x && to.y == from.y) || !inside_star(m, star, to)) continue;
    Move move{v, to, {}};
    try {
      move.metric = field.at(to.x, to.y);
    } catch (const fields::FieldError&) {
      continue;
    }
    m.sites[vi] = to, m.metrics[vi] = move.metric;
    const Score moved = score_at(m, v, around);
    m.sites[vi] = from, m.metrics[vi] = metric;
    if (moved.beats(best ? best->first : stay)) best = std::pair{moved, move};
  }
  if (best) best->first = Score{best->first.unit - stay.unit, stay.energy - best->first.energy};
  return best;
}

}  // namespace

Relocated relocate(const Mesh<double>& m, const fields::MetricField& field, bool quiet, int rounds) {
  Relocated r{m, 0, 0};
  const auto progress = progress_printer(quiet);
  constexpr int tries = 3;
  std::vector<int> refused(m.sites.size(), 0);  // how often a move was undone; the vertices on segments never move
  for (const auto& [a, b] : m.segments) refused[static_cast<std::size_t>(a)] = refused[static_cast<std::size_t>(b)] = tries;
  EdgeMeasures now = edge_measures(m);
  for (int round = 1; round <= rounds; ++round) {
    Mesh<double>& cur = r.mesh;
    const auto n = neighbours(cur);
    std::vector<std::vector<std::size_t>> star(cur.sites.size());
    for (std::size_t k = 0; k < cur.triangles.size(); ++k)
      for (int i : cur.triangles[k]) star[static_cast<std::size_t>(i)].push_back(k);
    std::vector<std::pair<Score, Move>> candidates;
    for (std::size_t v = 0; v < n.size(); ++v) {
      if (refused[v] >= tries || n[v].empty()) continue;
      if (auto p = proposal(cur, static_cast<int>(v), n[v], star[v], field)) candidates.push_back(std::move(*p));
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
      return a.first.unit != b.first.unit ? a.first.unit > b.first.unit : a.first.energy > b.first.energy;
    });
    DisjointNeighbourhoods apart(n);
    std::vector<Move> batch;
    for (const auto& [gain, move] : candidates)
      if (apart.admit({move.site})) batch.push_back(move);
    if (batch.empty()) break;
    std::vector<int> tried;
    for (const Move& mv : batch) tried.push_back(mv.site);
    std::size_t kept = 0;
    auto kept_batch = keep_certified(
        batch, n, [](const Move& mv) { return std::vector<int>{mv.site}; },
        [&](const std::vector<Move>& moves) {
          Mesh<double> moved = cur;
          for (const Move& mv : moves)
            moved.sites[static_cast<std::size_t>(mv.site)] = mv.to, moved.metrics[static_cast<std::size_t>(mv.site)] = mv.metric;
          return judged(std::move(moved), r.diagrams);
        },
        [&](const Trial& t) {  // kept only when better, so `now` is the kept mesh's
          const EdgeMeasures e = edge_measures(t.mesh);
          const bool better = e.unit_share > now.unit_share || (e.unit_share == now.unit_share && e.energy < now.energy);
          if (better) now = e;
          return better;
        },
        [&](const Move& mv) { ++refused[static_cast<std::size_t>(mv.site)]; });
    if (kept_batch) {
      kept = kept_batch->batch.size(), r.moves += kept;
      r.mesh = std::move(kept_batch->trial.mesh);
    }
    if (progress)
      progress("refine --relocate: round " + std::to_string(round) + ": " + std::to_string(kept) + " of " + std::to_string(tried.size()) +
               " vertices moved (" + std::to_string(r.moves) + " moves in all, " + std::to_string(r.diagrams) + " exact diagrams)");
    if (kept == 0)  // every round moves vertices or counts a refusal of each it tried
      for (int v : tried) ++refused[static_cast<std::size_t>(v)];
  }
  return r;
}

}  // namespace anisocert::cli
