// The geometric dual of D|Ω (LS §5), whether it is a triangulation (polygonalization) of Ω
// (triangulation_check.hpp, BWY §3.2.1), and the Theorem 7 verdict (LS Theorem 7).
#include "oracle/diagram/build.hpp"

#include <algorithm>
#include <set>

namespace anisocert::oracle::build {

namespace {

std::string pair_text(int a, int b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

int left_site_of(const Diagram& d, int h) { return d.cycles[d.half_edges[h].cycle].site; }

// The cycle rotated to its lexicographically least rotation: the canonical listing of a cyclic
// sequence. Rotating to the least site alone is not one when that site owns two sectors (a
// vertex where one cell meets itself): [0, 1, 0, 2] and [0, 2, 0, 1] are the same cycle, and which
// came out depended on where the germs' angular order began.
void least_rotation(std::vector<int>& cycle) {
  std::vector<int> best = cycle, rotated = cycle;
  for (std::size_t k = 1; k < cycle.size(); ++k) {
    std::rotate(rotated.begin(), rotated.begin() + 1, rotated.end());
    if (rotated < best) best = rotated;
  }
  cycle = std::move(best);
}

}  // namespace

void Builder::build_dual() {
  for (int n = 0; n < static_cast<int>(d_.nodes.size()); ++n) {
    const Node& node = d_.nodes[n];
    if (node.sites.size() < 3) continue;
    const auto& gs = germs_[n];
    if (gs.empty()) continue;  // a vertex of D|Ω on ∂Ω whose arcs all leave Ω at once
    // The sector after germ i (counter-clockwise) is on the left of germ i's outgoing half-edge;
    // after the incoming boundary piece lies the outside of Ω.
    // On ∂Ω the listing starts after the (last) incoming boundary piece; inside Ω it is a cycle,
    // listed canonically.
    const auto piece = std::find_if(gs.rbegin(), gs.rend(), [](const Germ& g) { return g.outgoing < 0; });
    const std::size_t start = piece == gs.rend() ? 0 : static_cast<std::size_t>(gs.rend() - piece) % gs.size();
    std::vector<int> owners;
    for (std::size_t k = 0; k < gs.size(); ++k) {
      const Germ& g = gs[(start + k) % gs.size()];
      if (g.outgoing >= 0) owners.push_back(left_site_of(d_, g.outgoing));
    }
    if (piece == gs.rend()) least_rotation(owners);
    std::set<int> distinct(owners.begin(), owners.end());
    (owners.size() == 3 && distinct.size() == 3 ? d_.dual_triangles : d_.dual_polygons).push_back({n, owners});
  }
}

void Builder::check_triangulation() {
  CellList cells;
  std::vector<int> vertex;
  for (const auto* list : {&d_.dual_triangles, &d_.dual_polygons})
    for (const DualCell& c : *list) cells.add(c.sites.data(), c.sites.size()), vertex.push_back(c.vertex);
  cells.name = [&vertex](std::size_t k) { return "the dual cell of vertex " + std::to_string(vertex[k]); };
  d_.dual_check = oracle::check_triangulation(EnclosedMesh(d_.input), cells);
}

void Builder::check_theorem7() {
  Theorem7& th = d_.theorem7;
  const auto& dom = d_.domain;
  const auto& corner_site = d_.corner_site;
  for (std::size_t k = 0; k < dom.size(); ++k)
    if (corner_site[k] < 0) th.reasons.push_back("corner " + std::to_string(k) + " of Ω is not a site");
  // "Let V be a set of sites in Ω": a site outside Ω can own arcs across ∂Ω that no edge's
  // endpoints own, and its dual triangles reach outside Ω (found when `dual` took Ω as the boundary
  // of a stopped run's one triangle while the other sites lay outside it).
  for (std::size_t v = 0; v < d_.input.sites.size(); ++v)
    if (!geometry::in_closed_polygon(d_.input.sites[v], d_.input.domain))
      th.reasons.push_back("site " + std::to_string(v) + " lies outside Ω");
  for (std::size_t a = 0; a < d_.arcs.size(); ++a)
    for (int k : d_.arcs[a].cut_by_edges) {
      const int p = corner_site[k], q = corner_site[(k + 1) % dom.size()];
      if (std::minmax(p, q) != std::minmax(d_.arcs[a].v, d_.arcs[a].w))
        th.reasons.push_back("arc " + std::to_string(a) + " of sites " + pair_text(d_.arcs[a].v, d_.arcs[a].w) +
                             " is cut by edge " + std::to_string(k) + " of Ω, whose endpoints are not its sites");
    }
  for (std::size_t a = 0; a < d_.arcs.size(); ++a)
    if (!d_.arcs[a].wedged) th.reasons.push_back("arc " + std::to_string(a) + " is not wedged");
  for (std::size_t n = 0; n < d_.nodes.size(); ++n)
    if (d_.nodes[n].sites.size() >= 2 && !d_.nodes[n].wedged)
      th.reasons.push_back("vertex " + std::to_string(n) + " is not wedged");
  th.preconditions_hold = th.reasons.empty();
  th.disagreement = th.preconditions_hold && !d_.dual_check.is_triangulation;
}

}  // namespace anisocert::oracle::build
