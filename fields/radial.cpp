// radial: r = |p − c|, c = (cx, cy), n = (p − c)/r, s = sech²((r − R)/δ), M as for shock:
// stretching across the circle of radius R (params cx = cy = 0.5, R = 0.25, delta = 0.05,
// h = 0.05, alpha = 9).
#include "fields/builtin.hpp"
#include "fields/stretch.hpp"

namespace anisocert::fields {

FieldEntry radial_field() {
  return {"radial", "stretched by 1 + α sech²((r − R)/δ) across the circle |p − c| = R",
          {{"cx", 0.5}, {"cy", 0.5}, {"R", 0.25}, {"delta", 0.05}, {"h", 0.05}, {"alpha", 9}}, [](const Parameters& p) {
            require_positive("radial", p, "delta"), require_positive("radial", p, "h"), require_positive("radial", p, "R");
            require_non_negative("radial", p, "alpha");
            const double cx = p.at("cx"), cy = p.at("cy"), R = p.at("R"), d = p.at("delta"), h = p.at("h"),
                         alpha = p.at("alpha");
            return MetricField{"radial", p, [cx, cy, R, d, h, alpha](double x, double y) {
                                 const double r = std::hypot(x - cx, y - cy);
                                 const double nx = r > 0 ? (x - cx) / r : 1, ny = r > 0 ? (y - cy) / r : 0;
                                 return stretched(nx, ny, sech2((r - R) / d), h, alpha);
                               }};
          }};
}

}  // namespace anisocert::fields
