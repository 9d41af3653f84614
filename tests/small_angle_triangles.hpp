#pragma once
// For the tests of LS and BWY at a small input angle, on a polygon under one metric M: the
// triangles of a finished run that fail the refiner's bound (an angle bound, a radius-edge bound,
// judged by the test in doubles from the M-lengths), each expected across the angle of one of the
// corners `sharp`: its shortest edge in M joins two split sites (no corner) inside that corner's
// two edges at one M-distance from it (squares within 2⁻¹⁰; refiners/common/corner_shells.hpp's
// exemption, written again here).
// Returns how many there are.
#include "geometry/mesh.hpp"
#include "predicates/orientation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace anisocert::test_support {

// The M-lengths of a triangle's edges (opposite vertices 0, 1, 2) and its M-area.
struct MetricTriangle {
  std::array<double, 3> side;
  double area;
  double smallest_angle_deg() const {
    double least = 180;
    for (int i = 0; i < 3; ++i) {
      const double a = side[static_cast<std::size_t>((i + 1) % 3)], b = side[static_cast<std::size_t>((i + 2) % 3)], c = side[static_cast<std::size_t>(i)];
      least = std::min(least, std::acos(std::clamp((a * a + b * b - c * c) / (2 * a * b), -1.0, 1.0)) * 180 / M_PI);
    }
    return least;
  }
  double radius_edge() const { return side[0] * side[1] * side[2] / (4 * area) / *std::min_element(side.begin(), side.end()); }
};

inline double metric_length2(const predicates::Sym2<double>& M, const predicates::Point2<double>& a, const predicates::Point2<double>& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return M.m11 * dx * dx + 2 * M.m12 * dx * dy + M.m22 * dy * dy;
}

template <class Good>
std::size_t skinny_across_corners(const geometry::Mesh<double>& mesh, const std::vector<predicates::Point2<double>>& corners,
                                  const std::vector<int>& sharp, const predicates::Sym2<double>& M, Good good) {
  const std::size_t n = corners.size();
  const auto inside = [](const predicates::Point2<double>& a, const predicates::Point2<double>& b, const predicates::Point2<double>& q) {
    return predicates::orientation(a, b, q) == Sign::zero && (q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y) > 0 &&
           (q.x - b.x) * (a.x - b.x) + (q.y - b.y) * (a.y - b.y) > 0;
  };
  std::size_t skinny = 0;
  for (const auto& t : mesh.triangles) {
    std::array<predicates::Point2<double>, 3> v{};
    for (std::size_t k = 0; k < 3; ++k) v[k] = mesh.sites[static_cast<std::size_t>(t[k])];
    const auto l2 = [&](int i, int j) { return metric_length2(M, v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(j)]); };
    const double orient = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    const MetricTriangle T{{std::sqrt(l2(1, 2)), std::sqrt(l2(0, 2)), std::sqrt(l2(0, 1))}, std::sqrt(M.m11 * M.m22 - M.m12 * M.m12) * std::abs(orient) / 2};
    if (good(T)) continue;
    ++skinny;
    bool across = false;
    for (const int c : sharp) {
      const auto &pc = corners[static_cast<std::size_t>(c)], &pu = corners[(static_cast<std::size_t>(c) + n - 1) % n], &pw = corners[(static_cast<std::size_t>(c) + 1) % n];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          if (i == j || t[static_cast<std::size_t>(i)] < static_cast<int>(n) || t[static_cast<std::size_t>(j)] < static_cast<int>(n) ||
              !inside(pc, pu, v[static_cast<std::size_t>(i)]) || !inside(pc, pw, v[static_cast<std::size_t>(j)]))
            continue;
          const double da = metric_length2(M, pc, v[static_cast<std::size_t>(i)]), db = metric_length2(M, pc, v[static_cast<std::size_t>(j)]);
          across = across || (l2(i, j) <= l2(i, 3 - i - j) && l2(i, j) <= l2(j, 3 - i - j) && std::abs(da - db) <= 0x1p-10 * std::min(da, db));
        }
    }
    EXPECT_TRUE(across) << "a triangle of smallest angle " << T.smallest_angle_deg() << "° away from the sharp corners' shells";
  }
  return skinny;
}

}  // namespace anisocert::test_support
