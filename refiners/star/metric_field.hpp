#pragma once
// Built-in metric fields for the refiners (issue 6), each a function (x, y) ↦ M(x, y), symmetric
// positive definite, in floating point (refiners are fast, not exact; their output is checked by
// the exact certifier). Unit length in M is the intended edge length.
//   constant  M = [m11 m12; m12 m22]                                    (params m11, m12, m22)
//   linear    M = diag(1/h_x², 1/h_y²), h_x = hx, h_y = h0 + 2(hx − h0)|y − 1/2|
//             (the 2D analogue of the UGAWG linear case; params hx = 0.1, h0 = 10⁻³)
//   shock     f = tanh((2x − sin 5y)/δ); n = ∇f/|∇f| ∝ (2, −5 cos 5y); s = sech²((2x − sin 5y)/δ);
//             M = ((1 + α s)/h)² n nᵀ + (1/h)² (I − n nᵀ): lengths across the level lines of f
//             shrink by up to 1 + α (params delta = 0.6, h = 0.05, alpha = 9)
//   radial    r = |p − c|, c = (cx, cy), n = (p − c)/r, s = sech²((r − R)/δ), M as for shock:
//             stretching across the circle of radius R (params cx = cy = 0.5, R = 0.25,
//             delta = 0.05, h = 0.05, alpha = 9)
#include "predicates/point.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace anisocert::refiners::star {

struct MetricField {
  std::string name;
  std::map<std::string, double> params;  // every parameter, defaults filled in
  std::function<predicates::Sym2<double>(double, double)> at;
};

// Throws std::invalid_argument naming an unknown field, an unknown parameter or a value out of range.
MetricField make_field(const std::string& name, const std::map<std::string, double>& params);
std::vector<std::string> field_names();

}  // namespace anisocert::refiners::star
