// constant: M = [m11 m12; m12 m22] everywhere (params m11 = m22 = 1, m12 = 0); in 3D the 3×3
// [m11 m12 m13; m12 m22 m23; m13 m23 m33] (the identity by default), positive definite by
// Sylvester's minors.
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

FieldEntry3 constant_field3() {
  return {"constant", "M = [m11 m12 m13; m12 m22 m23; m13 m23 m33]",
          {{"m11", 1}, {"m12", 0}, {"m13", 0}, {"m22", 1}, {"m23", 0}, {"m33", 1}}, [](const Parameters& p) {
            const predicates::Sym3<double> M{p.at("m11"), p.at("m12"), p.at("m13"), p.at("m22"), p.at("m23"), p.at("m33")};
            const double minor2 = M.m11 * M.m22 - M.m12 * M.m12;
            const double det = M.m11 * (M.m22 * M.m33 - M.m23 * M.m23) - M.m12 * (M.m12 * M.m33 - M.m23 * M.m13) +
                               M.m13 * (M.m12 * M.m23 - M.m22 * M.m13);
            if (!(M.m11 > 0 && minor2 > 0 && det > 0))
              throw std::invalid_argument("field constant: [m11 m12 m13; m12 m22 m23; m13 m23 m33] must be positive definite");
            return MetricField3{"constant", p, [M](double, double, double) { return M; }};
          }};
}

}  // namespace anisocert::fields
