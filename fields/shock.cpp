// shock: f = tanh((2x − sin 5y)/δ); n = ∇f/|∇f| ∝ (2, −5 cos 5y); s = sech²((2x − sin 5y)/δ);
// M = ((1 + α s)/h)² n nᵀ + (1/h)² (I − n nᵀ): lengths across the level lines of f shrink by up to
// 1 + α (params delta = 0.6, h = 0.05, alpha = 9).
#include "fields/builtin.hpp"
#include "fields/stretch.hpp"

namespace anisocert::fields {

FieldEntry shock_field() {
  return {"shock", "stretched by 1 + α sech²((2x − sin 5y)/δ) across the level lines of tanh((2x − sin 5y)/δ)",
          {{"delta", 0.6}, {"h", 0.05}, {"alpha", 9}}, [](const Parameters& p) {
            require_positive("shock", p, "delta"), require_positive("shock", p, "h");
            require_non_negative("shock", p, "alpha");
            const double d = p.at("delta"), h = p.at("h"), alpha = p.at("alpha");
            return MetricField{"shock", p, [d, h, alpha](double x, double y) {
                                 const double gx = 2, gy = -5 * std::cos(5 * y), g = std::hypot(gx, gy);
                                 return stretched(gx / g, gy / g, sech2((2 * x - std::sin(5 * y)) / d), h, alpha);
                               }};
          }};
}

}  // namespace anisocert::fields
