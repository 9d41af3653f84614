#include "property_tests/generators/domains.hpp"

#include <rapidcheck.h>

#include <array>
#include <cmath>

namespace anisocert::gen {

std::vector<predicates::Point2<double>> random_domain(bool reflex, bool obtuse_corners) {
  const int n = reflex ? *rc::gen::inRange(8, 10) : *rc::gen::inRange(5, 10);
  std::vector<std::array<long, 2>> q;
  for (int i = 0; i < n; ++i) {
    const double theta = 2 * M_PI * (i + 0.03 * *rc::gen::inRange(-10, 11)) / n;
    const double r = reflex ? (i == 0 ? 0.6 : 0.9 + 0.01 * *rc::gen::inRange(0, 11)) : 0.8 + 0.01 * *rc::gen::inRange(0, 21);
    q.push_back({std::lround(64 * r * std::cos(theta)), std::lround(64 * r * std::sin(theta))});
  }
  bool has_reflex = false;
  for (int i = 0; i < n; ++i) {
    const auto &a = q[(i + n - 1) % n], &v = q[i], &b = q[(i + 1) % n];
    const long turn = (v[0] - a[0]) * (b[1] - v[1]) - (v[1] - a[1]) * (b[0] - v[0]);
    RC_PRE(turn != 0);
    if (turn > 0 && obtuse_corners) RC_PRE((a[0] - v[0]) * (b[0] - v[0]) + (a[1] - v[1]) * (b[1] - v[1]) < 0);
    has_reflex = has_reflex || turn < 0;
  }
  RC_PRE(has_reflex == reflex);
  std::vector<predicates::Point2<double>> p;
  for (const auto& v : q) p.push_back({v[0] / 64.0, v[1] / 64.0});
  return p;
}

std::vector<predicates::Point2<double>> random_comb() {
  const int teeth = *rc::gen::inRange(1, 5);
  const double base = 4 / 32.0;
  std::vector<double> x, w, h;  // left end, width, height of each tooth
  double at = 0;
  for (int i = 0; i < teeth; ++i) {
    if (i > 0) at += *rc::gen::elementOf(std::vector<int>{1, 2, 4}) / 32.0;  // the gap
    x.push_back(at);
    w.push_back(*rc::gen::elementOf(std::vector<int>{1, 2, 4}) / 32.0);
    h.push_back(*rc::gen::inRange(4, 17) / 32.0);
    at += w.back();
  }
  // Counter-clockwise: the base, then the teeth from right to left along the top.
  std::vector<predicates::Point2<double>> p{{0, 0}, {at, 0}};
  for (int i = teeth - 1; i >= 0; --i) {
    if (i < teeth - 1) p.push_back({x[i] + w[i], base});
    p.push_back({x[i] + w[i], base + h[i]});
    p.push_back({x[i], base + h[i]});
    if (i > 0) p.push_back({x[i], base});
  }
  return p;
}

PslgInterior random_pslg_interior(std::size_t n) {
  PslgInterior x;
  if (*rc::gen::arbitrary<bool>()) return x;
  const int k = *rc::gen::inRange(1, 4);
  for (int i = 0; i < k; ++i) x.points.push_back({*rc::gen::inRange(-8, 9) / 32.0, *rc::gen::inRange(-8, 9) / 32.0});
  const int first = static_cast<int>(n);
  for (int i = 0; i + 1 < k; ++i)
    if (i == 0 || *rc::gen::arbitrary<bool>()) x.segments.emplace_back(first + i, first + i + 1);
  return x;
}

}  // namespace anisocert::gen
