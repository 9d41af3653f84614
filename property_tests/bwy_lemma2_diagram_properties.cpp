// BWY Lemma 2, geometric part: for adjacent triangles abc, abd dual to Voronoi vertices q_c, q_d,
// with γ the largest distortion over their edges, B > 1 a bound on their radius-edge ratios and
// (γ² − 1)(1 + γ)²(1 + 4γ)²B⁴ ≤ 1, every edge of V_Z (the diagram of {a, b, c, d} restricted to
// Z = ∩ B(x, (1 + 4γ)Bδ(a, b, c, d))) is wedged. Checked with the exact diagram on a convex
// polygon P ⊆ Z: the intersection of polygons inscribed in the four balls of a rational radius
// r ≤ 5Bδ_lo, where δ_lo ≤ δ is the shortest edge measured by any of the four metrics (so P ⊆ Z
// whichever metric the paper measures δ with, since 1 + 4γ ≥ 5).
#include "oracle/diagram/diagram.hpp"
#include "predicates/orientation.hpp"
#include "property_tests/bwy_zone.hpp"
#include "property_tests/generators/metrics.hpp"
#include "theory/bwy_section4.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>

using anisocert::Rational;
using namespace anisocert::gen;
using namespace anisocert::oracle;

RC_GTEST_PROP(BWY_L2, EdgesOfVZAreWedged, ()) {
  // Sites: a nearly regular pair of triangles in F-space, mapped back by F⁻¹.
  const int f11 = *rc::gen::inRange(1, 4), f12 = *rc::gen::inRange(-2, 3), f22 = *rc::gen::inRange(1, 4);
  const Frame F{Rational(f11), Rational(f12, 2), Rational(0), Rational(f22)};
  const int hc = *rc::gen::inRange(10, 17), hd = *rc::gen::inRange(10, 17), sc = *rc::gen::inRange(-3, 4),
            sd = *rc::gen::inRange(-3, 4);
  const std::vector<Point2<Rational>> u{{0, 0}, {1, 0}, {Rational(8 + sc, 16), Rational(hc, 16)}, {Rational(8 + sd, 16), Rational(-hd, 16)}};
  Mesh<Rational> in;
  std::vector<Frame> frames;
  for (int i = 0; i < 4; ++i) {
    in.sites.push_back(F.inverse(u[i]));
    const auto e = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-1, 2));
    frames.push_back({F.f11 + Rational(e[0], 1000), F.f12 + Rational(e[1], 1000), F.f21, F.f22 + Rational(e[2], 1000)});
    in.metrics.push_back(frames.back().metric());
  }
  const int a = 0, b = 1, c = 2, d = 3;
  // γ: a rational above the largest distortion over the edges of abc and abd; B from the condition.
  Rational g2 = 1;
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{a, b}, {a, c}, {b, c}, {a, d}, {b, d}})
    g2 = std::max(g2, tau2_above(in.metrics[x], in.metrics[y]));
  const Rational gamma = sqrt_above(g2);
  Rational B(2);
  while (anisocert::theory::bwy_lemma2_lhs(gamma, B) > 1) B -= Rational(1, 64);
  RC_PRE(B > 1);
  // δ_lo per triangle: the shortest edge by any of the four metrics (squared).
  auto delta2 = [&](int p, int q, int r) {
    Rational m = -1;
    for (const auto& M : in.metrics)
      for (const auto& [x, y] : std::vector<std::pair<int, int>>{{p, q}, {q, r}, {p, r}}) {
        const Rational l = d2(M, in.sites[x], in.sites[y]);
        if (m < 0 || l < m) m = l;
      }
    return m;
  };
  const Rational d2_abc = delta2(a, b, c), d2_abd = delta2(a, b, d);
  // Z's polygon P: radius² ≤ 25 B² max(δ_abc, δ_abd)².
  const Rational r = sqrt_below(25 * B * B * std::max(d2_abc, d2_abd));
  std::vector<Point2<Rational>> P;
  for (int i = 0; i < 4; ++i) {
    std::vector<Point2<Rational>> ball;
    for (const auto& dir : directions()) ball.push_back(at_distance(in.sites[i], frames[i], r, dir));
    P = i == 0 ? ball : clip(P, ball);
  }
  in.domain = P;
  const Diagram dg = compute_diagram(in);
  // The hypotheses: q_c and q_d are vertices of the diagram with radius-edge ratio at most B.
  int found = 0;
  for (const Node& n : dg.nodes) {
    if (n.kind != Node::Kind::voronoi || n.sites.size() != 3) continue;
    const bool is_c = n.sites == std::vector<int>{a, b, c}, is_d = n.sites == std::vector<int>{a, b, d};
    if (!is_c && !is_d) continue;
    ++found;
    // r(q)² ≤ B² δ² ⇔ Q_a(q) − B² δ_lo² ≤ 0 (δ_lo ≤ δ makes this a sufficient check).
    Conic q = distance_conic(dg.sheared.sites[a], dg.sheared.metrics[a]);
    q.f -= B * B * (is_c ? d2_abc : d2_abd);
    RC_PRE(n.at.sign_of(q) != anisocert::Sign::positive);
  }
  RC_PRE(found == 2);
  for (const Arc& arc : dg.arcs) RC_ASSERT(arc.wedged);
  RC_TAG(B >= Rational(3, 2) ? "B >= 1.5" : "1 < B < 1.5");
}
