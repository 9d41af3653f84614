#include "refiners/common/sites3.hpp"

#include "geometry/ellipse_box.hpp"
#include "numbers/shortest_decimal.hpp"
#include "predicates/metric.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::common {

std::string metric_text(const Sym3<double>& M) {
  return "[" + shortest_decimal(M.m11) + ", " + shortest_decimal(M.m12) + ", " + shortest_decimal(M.m13) + ", " +
         shortest_decimal(M.m22) + ", " + shortest_decimal(M.m23) + ", " + shortest_decimal(M.m33) + "]";
}

Sym3<double> Sites3::metric_at(const Point3<double>& q) const {
  const Sym3<double> M = field.at(q.x, q.y, q.z);
  const std::array<double, 6> m{M.m11, M.m12, M.m13, M.m22, M.m23, M.m33};
  const bool finite = std::all_of(m.begin(), m.end(), [](double t) { return std::isfinite(t); });
  if (!finite || !predicates::positive_definite(Sym3<Rational>{rational_from_double(M.m11), rational_from_double(M.m12),
                                                               rational_from_double(M.m13), rational_from_double(M.m22),
                                                               rational_from_double(M.m23), rational_from_double(M.m33)}))
    throw FieldError("the metric field " + field.name + " is not finite and positive definite at " + point_text(q) + ": " + metric_text(M));
  return M;
}

Box3 metric_ball_box(const Point3<double>& c, const Sym3<double>& M, double r2) {
  const auto [hx, hy, hz] = geometry::ellipsoid_half_widths(M, r2);
  return {c.x - hx, c.x + hx, c.y - hy, c.y + hy, c.z - hz, c.z + hz};
}

const std::vector<int>& Sites3::within(const Point3<double>& q, const Sym3<double>& M, double reach2) const {
  found_ = in(metric_ball_box(q, M, reach2 * (1 + 1e-9)));
  std::erase_if(found_, [&](int s) {
    return predicates::quadratic_form(M, points[s].x - q.x, points[s].y - q.y, points[s].z - q.z) > reach2;
  });
  return found_;
}

}  // namespace anisocert::refiners::common
