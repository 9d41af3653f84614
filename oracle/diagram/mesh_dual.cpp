#include "oracle/diagram/mesh_dual.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace anisocert::oracle {
namespace {

using Triple = std::array<int, 3>;

Triple sorted(Triple t) {
  std::sort(t.begin(), t.end());
  return t;
}

// Why triangle t (sorted) is not dual: the first pair of its vertices whose cells share no arc;
// else the Voronoi vertices owned by a pair of them, none of which the third owns.
std::string why_not_dual(const Diagram& d, const Triple& t, const std::set<std::pair<int, int>>& arc_pairs,
                         const std::map<std::pair<int, int>, std::vector<int>>& nodes_of_pair) {
  const std::array<std::pair<int, int>, 3> pairs{{{t[0], t[1]}, {t[1], t[2]}, {t[0], t[2]}}};
  for (const auto& [a, b] : pairs)
    if (!arc_pairs.count({a, b}))
      return "the cells of sites " + std::to_string(a) + " and " + std::to_string(b) + " share no Voronoi arc of D|Ω";
  const auto& [a, b] = pairs[0];
  const auto it = nodes_of_pair.find({a, b});
  if (it == nodes_of_pair.end())
    return "the Voronoi arcs of sites " + std::to_string(a) + " and " + std::to_string(b) + " end only on ∂Ω, never at a vertex owned by " +
           std::to_string(t[2]);
  std::string nodes;
  for (std::size_t k = 0; k < it->second.size() && k < 4; ++k) {
    const Node& n = d.nodes[it->second[k]];
    std::string owners;
    for (int s : n.sites) owners += (owners.empty() ? "" : ", ") + std::to_string(s);
    nodes += (nodes.empty() ? "" : "; ") + std::to_string(it->second[k]) + " owned by (" + owners + ")";
  }
  if (it->second.size() > 4) nodes += "; …";
  return "the Voronoi arcs of sites " + std::to_string(a) + " and " + std::to_string(b) + " end at vertices " + nodes + ", none owned by " +
         std::to_string(t[2]);
}

}  // namespace

MeshDual compare_with_dual(const Diagram& d, const std::vector<Triple>& triangles, std::size_t described) {
  std::set<Triple> dual, tie;
  for (const DualCell& c : d.dual_triangles) dual.insert(sorted({c.sites[0], c.sites[1], c.sites[2]}));
  for (const DualCell& c : d.dual_polygons) {
    const std::set<int> distinct(c.sites.begin(), c.sites.end());
    const std::vector<int> owners(distinct.begin(), distinct.end());
    for (std::size_t i = 0; i < owners.size(); ++i)
      for (std::size_t j = i + 1; j < owners.size(); ++j)
        for (std::size_t k = j + 1; k < owners.size(); ++k) tie.insert({owners[i], owners[j], owners[k]});
  }
  std::set<std::pair<int, int>> arc_pairs;
  for (const Arc& a : d.arcs) arc_pairs.emplace(a.v, a.w);
  std::map<std::pair<int, int>, std::vector<int>> nodes_of_pair;  // Voronoi vertices by pairs of their owners
  for (std::size_t n = 0; n < d.nodes.size(); ++n)
    if (d.nodes[n].kind == Node::Kind::voronoi)
      for (std::size_t i = 0; i < d.nodes[n].sites.size(); ++i)
        for (std::size_t j = i + 1; j < d.nodes[n].sites.size(); ++j)
          nodes_of_pair[{d.nodes[n].sites[i], d.nodes[n].sites[j]}].push_back(static_cast<int>(n));
  MeshDual r;
  r.described = described;
  std::set<Triple> in_mesh;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const Triple t = sorted(triangles[k]);
    in_mesh.insert(t);
    if (dual.count(t)) {
      r.kinds.push_back(MeshDual::Kind::dual), ++r.dual;
    } else if (tie.count(t)) {
      r.kinds.push_back(MeshDual::Kind::tie), ++r.ties;
    } else {
      r.kinds.push_back(MeshDual::Kind::not_dual), ++r.not_dual;
      if (r.not_dual_witnesses.size() < described)
        r.not_dual_witnesses.push_back({static_cast<int>(k), why_not_dual(d, t, arc_pairs, nodes_of_pair)});
    }
  }
  for (const DualCell& c : d.dual_triangles)
    if (!in_mesh.count(sorted({c.sites[0], c.sites[1], c.sites[2]})) && r.missing_count++ < described) r.missing.push_back(c);
  return r;
}

}  // namespace anisocert::oracle
