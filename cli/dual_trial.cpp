#include "cli/dual_trial.hpp"

#include "geometry/boundary_polygon.hpp"
#include "oracle/diagram/diagram.hpp"
#include "predicates/orientation.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace anisocert::cli {

using geometry::Mesh;

double length_in(const Mesh<double>& m, int a, int b, int in) {
  const auto& p = m.sites[static_cast<std::size_t>(a)];
  const auto& q = m.sites[static_cast<std::size_t>(b)];
  return std::sqrt(predicates::quadratic_form(m.metrics[static_cast<std::size_t>(in)], q.x - p.x, q.y - p.y));
}

double mean_length(const Mesh<double>& m, int a, int b) { return std::sqrt(length_in(m, a, b, a) * length_in(m, a, b, b)); }

std::vector<std::set<int>> neighbours(const Mesh<double>& m) {
  std::vector<std::set<int>> n(m.sites.size());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) n[static_cast<std::size_t>(t[i])].insert(t[(i + 1) % 3]), n[static_cast<std::size_t>(t[(i + 1) % 3])].insert(t[i]);
  return n;
}

bool unit_edge(const Mesh<double>& m, int a, int b) {
  const double la = length_in(m, a, b, a), lb = length_in(m, a, b, b);
  return la * la >= 0.5 && la * la <= 2 && lb * lb >= 0.5 && lb * lb <= 2;
}

EdgeMeasures edge_measures(const Mesh<double>& m) {
  std::size_t edges = 0, unit = 0;
  double sum = 0;
  const auto n = neighbours(m);
  for (std::size_t a = 0; a < n.size(); ++a)
    for (int b : n[a])
      if (static_cast<int>(a) < b) {
        const double l = std::log(mean_length(m, static_cast<int>(a), b));
        ++edges, unit += unit_edge(m, static_cast<int>(a), b), sum += l * l;
      }
  return edges == 0 ? EdgeMeasures{} : EdgeMeasures{double(unit) / double(edges), sum / double(edges)};
}

Trial judged(Mesh<double> m, std::size_t& diagrams) {
  Trial t;
  m.triangles.clear();
  t.mesh = std::move(m);
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
      for (int s : cell_sites(static_cast<std::size_t>(c))) t.near_failures.insert(s);
    for (const auto& [a, b] : d.dual_check.bad_edges) t.near_failures.insert(a), t.near_failures.insert(b);
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
  const auto n = neighbours(t.mesh);
  for (const auto& [a, b] : t.mesh.segments)
    if (!n[static_cast<std::size_t>(a)].count(b)) t.certified = false, t.near_failures.insert(a), t.near_failures.insert(b);
  if (!t.certified) t.mesh.triangles.clear();
  return t;
}

}  // namespace anisocert::cli
