#pragma once
// A vertex set judged by the oracle, for `refine --from`'s post-passes (--coarsen removes vertices,
// --relocate moves them): certified when the dual of the exact D|Ω of the sites is a triangulation
// of Ω and LS Theorem 7 is not contradicted (oracle/diagram, decided exactly), and that dual is then
// the mesh. It lives in cli/ because refiners never include the oracle. The lengths and the unit
// share here are doubles: they choose what to try, never a verdict.
#include "geometry/mesh.hpp"

#include <cstddef>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace anisocert::cli {

struct Trial {
  geometry::Mesh<double> mesh;  // the sites judged; with certified, their dual's triangles
  bool certified = false;
  std::set<int> near_failures;  // sites named by the oracle's failed check (indices into mesh)
};

// m's sites, metrics, domain and segments (its triangles ignored), judged; ++diagrams. Certified
// also needs every segment to be an edge of the dual (the certifier's validity asks it of the
// output); a segment that is not names its two ends.
Trial judged(geometry::Mesh<double> m, std::size_t& diagrams);

// One round's batch of changes (coarsen's removals, relocate's moves) is admitted while the closed
// neighbourhoods (a site and its neighbours, n) of the sites the changes touch are disjoint: a site
// the oracle names is then next to at most one change, and keep_certified puts back only that one.
// With only the touched sites apart, two changes sharing a neighbour were both charged with a
// failure there: on FreeFem's coarse shock square the first trial of 226 removals named 319 sites,
// 174 removals were put back and 25 kept (docs/refiners.md § Coarsening).
class DisjointNeighbourhoods {
 public:
  explicit DisjointNeighbourhoods(const std::vector<std::set<int>>& n) : n_(n), claimed_(n.size(), 0) {}
  // True, and the neighbourhoods claimed, when no site of the closed neighbourhoods of `sites` is
  // claimed yet.
  bool admit(const std::vector<int>& sites) {
    bool free = true;
    for (int v : sites) closed(v, [&](int u) { free = free && !claimed_[static_cast<std::size_t>(u)]; });
    if (free)
      for (int v : sites) closed(v, [&](int u) { claimed_[static_cast<std::size_t>(u)] = 1; });
    return free;
  }

 private:
  template <class Visit>
  void closed(int v, Visit visit) const {
    visit(v);
    for (int w : n_[static_cast<std::size_t>(v)]) visit(w);
  }

  const std::vector<std::set<int>>& n_;
  std::vector<char> claimed_;
};

// A round's batch, tried as coarsen and relocate both do: `trial(batch)` is the oracle's judgement
// of the batch applied (near_failures as sites of the current mesh). When it is not certified, the
// changes with a named site in the closed neighbourhood of one of their `touched(change)` sites are
// dropped, `refuse(change)` called for each, and the rest tried again (the earlier half, when none
// is named); when `better(trial)` rejects a certified mesh, the earlier half is tried; the first
// certified trial it accepts is kept (so `better` may record what it measured). At most 8 trials.
// Returns the batch kept and its trial, if any.
template <class Change>
struct Kept {
  std::vector<Change> batch;
  Trial trial;
};

template <class Change, class Touched, class TrialOf, class Better, class Refuse>
std::optional<Kept<Change>> keep_certified(std::vector<Change> batch, const std::vector<std::set<int>>& n, Touched touched, TrialOf trial,
                                           Better better, Refuse refuse) {
  for (int attempt = 0; attempt < 8 && !batch.empty(); ++attempt) {
    Trial t = trial(batch);
    if (!t.certified) {
      std::vector<Change> rest;
      for (const Change& c : batch) {
        bool near = false;
        for (int v : touched(c)) {
          near = near || t.near_failures.count(v) > 0;
          for (int w : n[static_cast<std::size_t>(v)]) near = near || t.near_failures.count(w) > 0;
        }
        if (near) refuse(c);
        else rest.push_back(c);
      }
      if (rest.size() == batch.size()) rest.resize(batch.size() / 2);
      batch = std::move(rest);
      continue;
    }
    if (!better(t)) {
      batch.resize(batch.size() / 2);
      continue;
    }
    return Kept<Change>{std::move(batch), std::move(t)};
  }
  return std::nullopt;
}

// |b − a| in a's metric, and in both (the geometric mean of the two).
double length_in(const geometry::Mesh<double>& m, int a, int b, int in);
double mean_length(const geometry::Mesh<double>& m, int a, int b);

// Each vertex's neighbours along the triangles' edges.
std::vector<std::set<int>> neighbours(const geometry::Mesh<double>& m);

// A unit edge: both lengths in [1/√2, √2].
bool unit_edge(const geometry::Mesh<double>& m, int a, int b);

// Over m's edges, in one pass: the share of unit edges, and the mean of (log ℓ)², ℓ an edge's
// geometric-mean length (0 for a unit mesh).
struct EdgeMeasures {
  double unit_share = 0, energy = 0;
};
EdgeMeasures edge_measures(const geometry::Mesh<double>& m);

}  // namespace anisocert::cli
