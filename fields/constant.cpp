// constant: M = [m11 m12; m12 m22] everywhere (params m11 = m22 = 1, m12 = 0).
#include "fields/builtin.hpp"

#include <stdexcept>

namespace anisocert::fields {

FieldEntry constant_field() {
  return {"constant", "M = [m11 m12; m12 m22]", {{"m11", 1}, {"m12", 0}, {"m22", 1}}, [](const Parameters& p) {
            const double a = p.at("m11"), b = p.at("m12"), c = p.at("m22");
            if (!(a > 0 && a * c - b * b > 0))
              throw std::invalid_argument("field constant: [m11 m12; m12 m22] must be positive definite");
            return MetricField{"constant", p, [a, b, c](double, double) { return predicates::Sym2<double>{a, b, c}; }};
          }};
}

}  // namespace anisocert::fields
