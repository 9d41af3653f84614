#pragma once
// The triangles a finished LS or BWY run may leave below its angle or shape bound: those of
// Shewchuk's small-angle exemption (refiners/common/corner_shells.hpp), recognised here apart from
// that code, exactly. Corner c of Ω (site c of the mesh) is sharp when its edges meet at less than
// 60° in its metric M_c, u·w > 0 and 4(u·w)² > |u|²|w|² in M_c; the triangle is exempt when its
// shortest edge in M_c (none shorter) joins a site on each of c's edges, neither c, whose squared
// M_c-distances from c are within a factor 2.
#include "geometry/mesh.hpp"
#include "predicates/orientation.hpp"
#include "property_tests/generators/metrics.hpp"

#include <array>

namespace anisocert::gen {

inline bool exempt_at_sharp_corner(const geometry::Mesh<Rational>& m, const std::array<int, 3>& t) {
  const std::size_t n = m.domain.size();
  const auto on = [](const Point2<Rational>& a, const Point2<Rational>& b, const Point2<Rational>& q) {
    return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) == 0 && (q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y) > 0 &&
           (q.x - b.x) * (a.x - b.x) + (q.y - b.y) * (a.y - b.y) >= 0;
  };
  for (std::size_t c = 0; c < n; ++c) {
    const Point2<Rational>&pc = m.domain[c], &pu = m.domain[(c + n - 1) % n], &pw = m.domain[(c + 1) % n];
    const Sym2<Rational>& M = m.metrics[c];
    const Rational ux = pu.x - pc.x, uy = pu.y - pc.y, wx = pw.x - pc.x, wy = pw.y - pc.y;
    const Rational uw = M.m11 * ux * wx + M.m12 * (ux * wy + uy * wx) + M.m22 * uy * wy;
    if (!(uw > 0 && 4 * uw * uw > d2(M, pc, pu) * d2(M, pc, pw))) continue;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>(j)], r = t[static_cast<std::size_t>(3 - i - j)];
        if (i == j || a == static_cast<int>(c) || b == static_cast<int>(c)) continue;
        const Point2<Rational>&p = m.sites[static_cast<std::size_t>(a)], &q = m.sites[static_cast<std::size_t>(b)], &o = m.sites[static_cast<std::size_t>(r)];
        if (!on(pc, pu, p) || !on(pc, pw, q)) continue;
        const Rational pq = d2(M, p, q), dp = d2(M, pc, p), dq = d2(M, pc, q);
        if (pq <= d2(M, p, o) && pq <= d2(M, q, o) && dp <= 2 * dq && dq <= 2 * dp) return true;
      }
  }
  return false;
}

}  // namespace anisocert::gen
