#pragma once
// The metric of the shock and radial fields: lengths across a direction n shrink by 1 + α s,
//   M = ((1 + α s)/h)² n nᵀ + (1/h)² (I − n nᵀ)  for a unit vector n and s ∈ [0, 1],
// with s = sech² of a signed distance over a width (1 on the feature, 0 far from it).
#include "predicates/point.hpp"

#include <cmath>

namespace anisocert::fields {

inline predicates::Sym2<double> stretched(double nx, double ny, double s, double h, double alpha) {
  const double across = std::pow((1 + alpha * s) / h, 2), along = 1 / (h * h);
  return {across * nx * nx + along * ny * ny, (across - along) * nx * ny, across * ny * ny + along * nx * nx};
}

// sech²(u), 0 where cosh overflows.
inline double sech2(double u) {
  const double c = std::cosh(u);
  return std::isfinite(c) ? 1 / (c * c) : 0;
}

}  // namespace anisocert::fields
