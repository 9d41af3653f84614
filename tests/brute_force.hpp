#pragma once
// The brute-force check of the exact diagram (LS Definition 1): at every point of a
// (k+1) × (k+1) grid over the domain's bounding box that lies in Ω, the owners of what the oracle
// says contains the point must be exactly its nearest sites, computed from the definition.
#include "oracle/diagram/diagram.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace anisocert::test_support {

inline void expect_brute_force_agrees(const oracle::Diagram& d, int k) {
  Rational x0 = d.input.domain[0].x, x1 = x0, y0 = d.input.domain[0].y, y1 = y0;
  for (const auto& p : d.input.domain)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  int located = 0;
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j <= k; ++j) {
      const predicates::Point2<Rational> p{x0 + (x1 - x0) * i / k, y0 + (y1 - y0) * j / k};
      oracle::Location loc;
      try {
        loc = oracle::locate(d, p);
      } catch (const std::invalid_argument&) {
        continue;  // outside a non-convex domain
      }
      ++located;
      EXPECT_EQ(loc.owners, oracle::nearest_sites(d.input, p))
          << "at (" << p.x << ", " << p.y << "), location kind " << static_cast<int>(loc.kind) << " index " << loc.index;
    }
  EXPECT_GT(located, 0);
}

}  // namespace anisocert::test_support
