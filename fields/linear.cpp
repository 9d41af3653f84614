// linear: M = diag(1/h_x², 1/h_y²), h_x = hx, h_y = h0 + 2(hx − h0)|y − 1/2| (the 2D analogue of
// the UGAWG linear case; params hx = 0.1, h0 = 10⁻³).
#include "fields/builtin.hpp"

#include <cmath>

namespace anisocert::fields {

FieldEntry linear_field() {
  return {"linear", "M = diag(1/hx², 1/hy²), hy = h0 + 2(hx − h0)|y − 1/2|", {{"hx", 0.1}, {"h0", 1e-3}},
          [](const Parameters& p) {
            require_positive("linear", p, "hx"), require_positive("linear", p, "h0");
            const double hx = p.at("hx"), h0 = p.at("h0");
            return MetricField{"linear", p, [hx, h0](double, double y) {
                                 const double hy = h0 + 2 * (hx - h0) * std::abs(y - 0.5);
                                 return predicates::Sym2<double>{1 / (hx * hx), 0, 1 / (hy * hy)};
                               }};
          }};
}

}  // namespace anisocert::fields
