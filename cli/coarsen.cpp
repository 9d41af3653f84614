#include "cli/coarsen.hpp"

#include "cli/output.hpp"
#include "geometry/boundary_polygon.hpp"
#include "oracle/diagram/diagram.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace anisocert::cli {
namespace {

using geometry::Mesh;

// |b − a| in M_in (doubles: a choice).
double length(const Mesh<double>& m, int a, int b, int in) {
  const auto& p = m.sites[static_cast<std::size_t>(a)];
  const auto& q = m.sites[static_cast<std::size_t>(b)];
  return std::sqrt(predicates::quadratic_form(m.metrics[static_cast<std::size_t>(in)], q.x - p.x, q.y - p.y));
}
double mean_length(const Mesh<double>& m, int a, int b) { return std::sqrt(length(m, a, b, a) * length(m, a, b, b)); }

std::vector<std::set<int>> neighbours(const Mesh<double>& m) {
  std::vector<std::set<int>> n(m.sites.size());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) n[static_cast<std::size_t>(t[i])].insert(t[(i + 1) % 3]), n[static_cast<std::size_t>(t[(i + 1) % 3])].insert(t[i]);
  return n;
}

// The share of unit edges (both lengths in [1/√2, √2]), in doubles.
double unit_share(const Mesh<double>& m) {
  std::size_t edges = 0, unit = 0;
  const auto n = neighbours(m);
  for (std::size_t a = 0; a < n.size(); ++a)
    for (int b : n[a])
      if (static_cast<int>(a) < b) {
        ++edges;
        const double la = length(m, static_cast<int>(a), b, static_cast<int>(a)), lb = length(m, static_cast<int>(a), b, b);
        unit += la * la >= 0.5 && la * la <= 2 && lb * lb >= 0.5 && lb * lb <= 2;
      }
  return edges == 0 ? 0 : double(unit) / double(edges);
}

struct Trial {
  Mesh<double> mesh;
  std::vector<int> origin;  // each site's index in the mesh tried from
  bool certified = false;
  std::set<int> near_failures;  // sites (of the mesh tried from) named by the oracle's failed check
};

// m without the sites `gone`, judged by the oracle: certified when the dual of the exact D|Ω of
// the rest is a triangulation of Ω (and Theorem 7 is not contradicted); that dual is then the mesh.
Trial without(const Mesh<double>& m, const std::vector<int>& gone, std::size_t& diagrams) {
  Trial t;
  std::vector<int> index(m.sites.size(), 0);
  for (int g : gone) index[static_cast<std::size_t>(g)] = -1;
  for (std::size_t k = 0; k < m.sites.size(); ++k)
    if (index[k] == 0) {
      index[k] = static_cast<int>(t.origin.size());
      t.origin.push_back(static_cast<int>(k));
      t.mesh.sites.push_back(m.sites[k]), t.mesh.metrics.push_back(m.metrics[k]);
    }
  t.mesh.domain = m.domain;
  for (const auto& [a, b] : m.segments) t.mesh.segments.push_back({index[static_cast<std::size_t>(a)], index[static_cast<std::size_t>(b)]});
  Mesh<Rational> in = geometry::exact(t.mesh);
  in.segments.clear();
  in.domain = geometry::without_straight_corners(in.domain);
  ++diagrams;
  oracle::Diagram d;
  try {
    d = oracle::compute_diagram(in, oracle::DiagramOptions{});
  } catch (const std::domain_error&) {  // declined (a degenerate configuration): not certified, nowhere in particular
    return t;
  }
  t.certified = d.dual_check.is_triangulation && !d.theorem7.disagreement;
  if (!t.certified) {
    const auto cell_sites = [&](std::size_t k) -> const std::vector<int>& {
      return k < d.dual_triangles.size() ? d.dual_triangles[k].sites : d.dual_polygons[k - d.dual_triangles.size()].sites;
    };
    for (int c : d.dual_check.bad_cells)
      for (int s : cell_sites(static_cast<std::size_t>(c))) t.near_failures.insert(t.origin[static_cast<std::size_t>(s)]);
    for (const auto& [a, b] : d.dual_check.bad_edges)
      t.near_failures.insert(t.origin[static_cast<std::size_t>(a)]), t.near_failures.insert(t.origin[static_cast<std::size_t>(b)]);
    return t;
  }
  const auto add = [&](int a, int b, int c) {
    const auto& s = t.mesh.sites;
    const Sign o = predicates::orientation(s[static_cast<std::size_t>(a)], s[static_cast<std::size_t>(b)], s[static_cast<std::size_t>(c)]);
    t.mesh.triangles.push_back(o == Sign::negative ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
  };
  for (const auto& c : d.dual_triangles) add(c.sites[0], c.sites[1], c.sites[2]);
  for (const auto& c : d.dual_polygons)  // a tie: its polygon fanned (compare_with_dual calls each a tie)
    for (std::size_t i = 1; i + 1 < c.sites.size(); ++i) add(c.sites[0], c.sites[i], c.sites[i + 1]);
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
  double share = unit_share(m);
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
    for (int attempt = 0; attempt < 8 && !batch.empty(); ++attempt) {
      Trial t = without(cur, batch, c.diagrams);
      if (!t.certified) {
        // Put back the removals next to what the oracle named (else the later half of the batch).
        std::vector<int> rest;
        for (int v : batch) {
          bool near = t.near_failures.count(v) > 0;
          for (int w : n[static_cast<std::size_t>(v)]) near = near || t.near_failures.count(w) > 0;
          if (near) ++refused[static_cast<std::size_t>(origin[static_cast<std::size_t>(v)])];
          else rest.push_back(v);
        }
        if (rest.size() == batch.size()) rest.resize(batch.size() / 2);
        batch = std::move(rest);
        continue;
      }
      const double s = unit_share(t.mesh);
      if (s <= share) {
        batch.resize(batch.size() / 2);
        continue;
      }
      share = s, kept = batch.size(), c.removed += kept;
      std::vector<int> next(t.origin.size());
      for (std::size_t k = 0; k < next.size(); ++k) next[k] = origin[static_cast<std::size_t>(t.origin[k])];
      origin = std::move(next);
      c.mesh = std::move(t.mesh);
      break;
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
