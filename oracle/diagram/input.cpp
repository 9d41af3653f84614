#include "oracle/diagram/input.hpp"

namespace anisocert::oracle {

Conic distance_conic(const Point2<Rational>& v, const Sym2<Rational>& M) {
  // (x − vx, y − vy) M (x − vx, y − vy)ᵀ expanded.
  const Rational gx = M.m11 * v.x + M.m12 * v.y, gy = M.m12 * v.x + M.m22 * v.y;
  return {M.m11, 2 * M.m12, M.m22, -2 * gx, -2 * gy, v.x * gx + v.y * gy};
}

Conic bisector_conic(const Mesh<Rational>& in, int v, int w) {
  const Conic a = distance_conic(in.sites[v], in.metrics[v]), b = distance_conic(in.sites[w], in.metrics[w]);
  return {a.a - b.a, a.b - b.b, a.c - b.c, a.d - b.d, a.e - b.e, a.f - b.f};
}

Conic wedge_form(const Mesh<Rational>& in, int from, int to) {
  const Point2<Rational>& v = in.sites[from];
  const Point2<Rational>& w = in.sites[to];
  const Sym2<Rational>& M = in.metrics[from];
  const Rational gx = M.m11 * (w.x - v.x) + M.m12 * (w.y - v.y), gy = M.m12 * (w.x - v.x) + M.m22 * (w.y - v.y);
  return {0, 0, 0, gx, gy, -(gx * v.x + gy * v.y)};
}

Conic shear_conic(const Conic& G, const Rational& s) {
  // x ↦ x + s y: a(x + sy)² + b(x + sy)y + c y² + d(x + sy) + e y + f
  return {G.a, 2 * s * G.a + G.b, G.a * s * s + G.b * s + G.c, G.d, G.d * s + G.e, G.f};
}

Mesh<Rational> shear_input(const Mesh<Rational>& in, const Rational& s) {
  Mesh<Rational> out;
  for (const auto& p : in.sites) out.sites.push_back({p.x + s * p.y, p.y});
  for (const auto& M : in.metrics)  // S⁻ᵀ M S⁻¹, S⁻¹ = [1 −s; 0 1]
    out.metrics.push_back({M.m11, M.m12 - s * M.m11, M.m22 - 2 * s * M.m12 + s * s * M.m11});
  for (const auto& p : in.domain) out.domain.push_back({p.x + s * p.y, p.y});
  return out;
}

Rational choose_shear(const Mesh<Rational>& in, const std::vector<std::pair<int, int>>& pairs) {
  // A conic G(x, y) = 0 sheared by s, G(x − s y, y), has y² coefficient a s² − b s + c = q(−s, 1).
  // Each bisector and each edge excludes at most two values of s, so the search ends.
  for (int k = 0;; ++k) {
    const Rational s = Rational((k + 1) / 2 * (k % 2 == 0 ? -1 : 1), 7);
    auto vertical = [&](const Conic& G) {
      const Conic H = shear_conic(G, -s);
      return H.degree() == 2 ? H.c == 0 : H.e == 0;
    };
    bool ok = true;
    for (std::size_t i = 0; ok && i < in.domain.size(); ++i)
      ok = !vertical(line_conic(in.domain[i], in.domain[(i + 1) % in.domain.size()]));
    for (std::size_t i = 0; ok && i < pairs.size(); ++i) ok = !vertical(bisector_conic(in, pairs[i].first, pairs[i].second));
    if (ok) return s;
  }
}

}  // namespace anisocert::oracle
