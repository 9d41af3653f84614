// The UGAWG benchmark's 3D metric fields (github.com/UGAWG/adapt-benchmarks, cube/README.md and
// cube-cylinder/README.md), each with its parameter h0 (default 10⁻³):
//  - ugawg-linear: M = diag(h_x⁻², h_y⁻², h_z⁻²), h_x = h_y = 0.1, h_z = h0 + 2(0.1 − h0)|z − 0.5|;
//  - ugawg-polar1: M = R diag(h_r⁻², h_t⁻², h_z⁻²) Rᵀ, R the rotation by t = atan2(y, x) about z
//    (its columns the radial and the θ directions), r = √(x² + y²), h_z = h_t = 0.1,
//    h_r = h0 + 2(0.1 − h0)|r − 0.5|;
//  - ugawg-polar2: polar1 with h_t refined along θ near the layer: d = 10(0.6 − r),
//    h_t = 0.1 when d < 0, else d/40 + (1 − d)·0.1. Its domain is the cube minus the cylinder
//    r < 0.5; where h_t ≤ 0 (r ≤ 7/15) the field has no metric (FieldError naming the point).
// On the axis (r = 0) the radial direction is taken as x (polar1 is isotropic there: h_r = h_t).
#include "fields/builtin.hpp"

#include <cmath>

namespace anisocert::fields {

FieldEntry3 ugawg_linear_field() {
  return {"ugawg-linear", "M = diag(1/0.1², 1/0.1², 1/hz²), hz = h0 + 2(0.1 − h0)|z − 1/2|", {{"h0", 1e-3}},
          [](const Parameters& p) {
            require_positive("ugawg-linear", p, "h0");
            const double h0 = p.at("h0");
            return MetricField3{"ugawg-linear", p, [h0](double, double, double z) {
                                  const double hz = h0 + 2 * (0.1 - h0) * std::abs(z - 0.5);
                                  return predicates::Sym3<double>{1 / (0.1 * 0.1), 0, 0, 1 / (0.1 * 0.1), 0, 1 / (hz * hz)};
                                }};
          }};
}

FieldEntry3 ugawg_polar_field(int variant) {
  const std::string name = "ugawg-polar" + std::to_string(variant);
  const std::string ht = variant == 1 ? "ht = 0.1" : "ht = 0.1 if d < 0 else d/40 + (1 − d)·0.1, d = 10(0.6 − r)";
  return {name, "M = R diag(1/hr², 1/ht², 1/0.1²) Rᵀ, R the rotation by atan2(y, x) about z, hr = h0 + 2(0.1 − h0)|r − 1/2|, " + ht,
          {{"h0", 1e-3}}, [name, variant](const Parameters& p) {
            require_positive(name, p, "h0");
            const double h0 = p.at("h0");
            return MetricField3{name, p, [name, variant, h0](double x, double y, double) {
                                  const double r = std::hypot(x, y), c = r > 0 ? x / r : 1, s = r > 0 ? y / r : 0;
                                  const double hr = h0 + 2 * (0.1 - h0) * std::abs(r - 0.5);
                                  const double d = 10 * (0.6 - r);
                                  const double ht = variant == 1 || d < 0 ? 0.1 : d / 40 + (1 - d) * 0.1;
                                  if (!(ht > 0))
                                    throw FieldError("field " + name + " has no metric at r = " + std::to_string(r) +
                                                     " (h_t = " + std::to_string(ht) + "; its domain is r >= 1/2)");
                                  const double a = 1 / (hr * hr), b = 1 / (ht * ht), zz = 1 / (0.1 * 0.1);
                                  return predicates::Sym3<double>{c * c * a + s * s * b, c * s * (a - b), 0, s * s * a + c * c * b, 0, zz};
                                }};
          }};
}

}  // namespace anisocert::fields
