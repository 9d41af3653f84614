#include "refiners/bwy/local_embedding.hpp"

#include "predicates/orientation.hpp"
#include "refiners/common/domain.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace anisocert::refiners::bwy {
namespace {

using predicates::Point2;

std::string edge_text(int a, int b) { return std::to_string(a) + "–" + std::to_string(b); }

// The vertex of triangle t that is neither a nor b.
int third(const DualTriangles& T, int t, int a, int b) {
  for (int u : T.triangle(t).sites)
    if (u != a && u != b) return u;
  return a;  // a triangle with a repeated site: never made (sites are distinct)
}

// The triangles on an edge of t whose third vertex is on t's side of it, or only the first found.
std::vector<int> overlapping(const DualTriangles& T, int t, const std::vector<Point2<double>>& sites, bool first_only) {
  const auto& tri = T.triangle(t);
  const auto side = [&](int a, int b, int c) {
    return predicates::orientation(sites[static_cast<std::size_t>(a)], sites[static_cast<std::size_t>(b)], sites[static_cast<std::size_t>(c)]);
  };
  std::vector<int> found;
  for (int i = 0; i < 3; ++i) {
    const int a = tri.sites[static_cast<std::size_t>(i)], b = tri.sites[static_cast<std::size_t>((i + 1) % 3)],
              c = tri.sites[static_cast<std::size_t>((i + 2) % 3)];
    for (int u : T.on_edge(a, b))
      if (u != t && side(a, b, third(T, u, a, b)) == side(a, b, c)) {
        found.push_back(u);
        if (first_only) return found;
      }
  }
  return found;
}

}  // namespace

bool overlaps(const DualTriangles& T, int t, const std::vector<Point2<double>>& sites) {
  return T.triangle(t).flat || !overlapping(T, t, sites, true).empty();
}

std::vector<int> overlapping(const DualTriangles& T, int t, const std::vector<Point2<double>>& sites) {
  return overlapping(T, t, sites, false);
}

std::string embedding_failure(const DualTriangles& T, const std::vector<Point2<double>>& sites, const std::vector<Constraint>& subsegments) {
  std::vector<char> used(sites.size(), 0);
  const std::vector<int> alive = T.alive();
  for (int t : alive) {
    const auto& tri = T.triangle(t);
    if (tri.flat) return "the triangle of sites " + common::trio_text(tri.sites) + " is flat";
    for (int u : tri.sites) used[static_cast<std::size_t>(u)] = 1;
  }
  for (std::size_t u = 0; u < used.size(); ++u)
    if (!used[u]) return "site " + std::to_string(u) + " is a vertex of no triangle";
  std::set<std::pair<int, int>> boundary;
  for (const Constraint& s : subsegments) {
    const std::size_t in = T.on_edge(s.a, s.b).size();
    if (s.on_boundary ? in != 1 : in != 2) return "the subsegment " + edge_text(s.a, s.b) + " is in " + std::to_string(in) + " triangles";
    if (s.on_boundary) boundary.insert(std::minmax(s.a, s.b));
  }
  for (int t : alive) {
    const auto& tri = T.triangle(t);
    for (int i = 0; i < 3; ++i) {
      const int a = tri.sites[static_cast<std::size_t>(i)], b = tri.sites[static_cast<std::size_t>((i + 1) % 3)];
      if (boundary.count(std::minmax(a, b))) continue;
      const std::size_t on = T.on_edge(a, b).size();
      if (on != 2) return "the edge " + edge_text(a, b) + " is in " + std::to_string(on) + " triangles";
    }
    if (overlaps(T, t, sites)) return "the triangle of sites " + common::trio_text(tri.sites) + " overlaps a neighbour";
  }
  return {};
}

}  // namespace anisocert::refiners::bwy
