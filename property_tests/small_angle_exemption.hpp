#pragma once
// The triangles a finished LS or BWY run may leave below its angle or shape bound: those across a
// small input angle (refiners/common/corner_shells.hpp), recognised here apart from that code,
// exactly. Two segments of the PSLG X (Ω's edges, interior segments) at a vertex c of X (site c of
// the mesh) form a small angle when they meet at less than 60° in c's metric M_c: u·w > 0 and
// 4(u·w)² > |u|²|w|² in M_c. The triangle is exempt when its shortest edge in M_c (none shorter)
// joins two sites that are no vertex of X, one strictly inside each of the two segments, whose
// squared M_c-distances from c differ by at most 2⁻¹⁰ of either.
#include "geometry/mesh.hpp"
#include "property_tests/generators/metrics.hpp"
#include "refiners/common/domain.hpp"

#include <algorithm>
#include <array>

namespace anisocert::gen {

inline bool exempt_at_small_angle(const geometry::Mesh<Rational>& m, const refiners::common::Domain& X, const std::array<int, 3>& t) {
  const std::size_t vertices = X.vertices().size();
  const auto inside = [](const Point2<Rational>& a, const Point2<Rational>& b, const Point2<Rational>& q) {
    return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) == 0 && (q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y) > 0 &&
           (q.x - b.x) * (a.x - b.x) + (q.y - b.y) * (a.y - b.y) > 0;
  };
  const auto vertex = [&](int k) { return Point2<Rational>{Rational(X.vertices()[static_cast<std::size_t>(k)].x), Rational(X.vertices()[static_cast<std::size_t>(k)].y)}; };
  for (std::size_t e = 0; e < X.segment_count(); ++e)
    for (std::size_t f = 0; f < X.segment_count(); ++f) {
      const auto [e0, e1] = X.segment_ends(e);
      const auto [f0, f1] = X.segment_ends(f);
      // c: their common end; u, w: their other ends
      const int c = e0 == f0 || e0 == f1 ? e0 : e1 == f0 || e1 == f1 ? e1 : -1;
      if (e == f || c < 0) continue;
      const int u = e0 == c ? e1 : e0, w = f0 == c ? f1 : f0;
      const Point2<Rational> pc = vertex(c), pu = vertex(u), pw = vertex(w);
      const Sym2<Rational>& M = m.metrics[static_cast<std::size_t>(c)];
      const Rational ux = pu.x - pc.x, uy = pu.y - pc.y, wx = pw.x - pc.x, wy = pw.y - pc.y;
      const Rational uw = M.m11 * ux * wx + M.m12 * (ux * wy + uy * wx) + M.m22 * uy * wy;
      if (!(uw > 0 && 4 * uw * uw > d2(M, pc, pu) * d2(M, pc, pw))) continue;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const std::size_t a = static_cast<std::size_t>(t[static_cast<std::size_t>(i)]), b = static_cast<std::size_t>(t[static_cast<std::size_t>(j)]);
          if (i == j || a < vertices || b < vertices) continue;
          const Point2<Rational>&p = m.sites[a], &q = m.sites[b], &o = m.sites[static_cast<std::size_t>(t[static_cast<std::size_t>(3 - i - j)])];
          if (!inside(pc, pu, p) || !inside(pc, pw, q)) continue;
          const Rational pq = d2(M, p, q), dp = d2(M, pc, p), dq = d2(M, pc, q);
          if (pq <= d2(M, p, o) && pq <= d2(M, q, o) && abs(dp - dq) * 1024 <= std::min(dp, dq)) return true;
        }
    }
  return false;
}

}  // namespace anisocert::gen
