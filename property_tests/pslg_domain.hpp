#pragma once
// A random domain with the rest of a random PSLG (generators/domains.hpp's random_pslg_interior),
// as the refiners take it: Ω's corners, its points and interior segments. A draw that Domain
// refuses by name (two points at one place, a point on a segment) keeps its corners only. Tagged.
#include "geometry/mesh.hpp"
#include "geometry/polygon.hpp"
#include "property_tests/generators/domains.hpp"
#include "refiners/common/domain.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

namespace anisocert::gen {

inline refiners::common::Domain domain_with_interior(const std::vector<predicates::Point2<double>>& corners) {
  const PslgInterior x = random_pslg_interior(corners.size());
  try {
    refiners::common::Domain d(corners, x.points, x.segments);
    RC_TAG(x.points.empty() ? "no interior features" : x.segments.empty() ? "interior points" : "interior points and segments");
    return d;
  } catch (const refiners::common::DomainError& e) {
    RC_TAG("interior features refused");
    RC_LOG() << e.what() << "\n";
    return refiners::common::Domain(corners);
  }
}

// Every segment of the PSLG (Ω's edges and its interior segments, whose vertices are the mesh's
// first sites) is a union of mesh edges: the sites exactly on it, in order, are joined by edges
// of the triangles. Decided from the domain, not from the segments the refiner reports.
inline void assert_pslg_segments_are_edges(const geometry::Mesh<Rational>& m, const refiners::common::Domain& domain) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.triangles)
    for (std::size_t i = 0; i < 3; ++i) edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
  for (std::size_t e = 0; e < domain.segment_count(); ++e) {
    const auto [a, b] = domain.segment_ends(e);
    const auto &pa = m.sites[static_cast<std::size_t>(a)], &pb = m.sites[static_cast<std::size_t>(b)];
    std::vector<std::pair<Rational, int>> on;
    for (std::size_t s = 0; s < m.sites.size(); ++s)
      if (geometry::on_segment(m.sites[s], pa, pb))
        on.emplace_back((m.sites[s].x - pa.x) * (pb.x - pa.x) + (m.sites[s].y - pa.y) * (pb.y - pa.y), static_cast<int>(s));
    std::sort(on.begin(), on.end());
    for (std::size_t i = 0; i + 1 < on.size(); ++i) RC_ASSERT(edges.count(std::minmax(on[i].second, on[i + 1].second)) == 1u);
  }
}

}  // namespace anisocert::gen
