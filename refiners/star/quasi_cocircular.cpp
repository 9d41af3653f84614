#include "refiners/star/quasi_cocircular.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::star {

bool quasi_cocircular(const predicates::Point2<double>& a, const predicates::Point2<double>& b,
                      const predicates::Point2<double>& c, const predicates::Point2<double>& d,
                      const predicates::Sym2<double>& M, double gamma0) {
  const double u[3][2] = {{a.x - d.x, a.y - d.y}, {b.x - d.x, b.y - d.y}, {c.x - d.x, c.y - d.y}};
  const double cof[3] = {u[1][0] * u[2][1] - u[1][1] * u[2][0], u[2][0] * u[0][1] - u[2][1] * u[0][0],
                         u[0][0] * u[1][1] - u[0][1] * u[1][0]};
  double c11 = 0, c12 = 0, c22 = 0;
  for (int i = 0; i < 3; ++i)
    c11 += cof[i] * u[i][0] * u[i][0], c12 += cof[i] * u[i][0] * u[i][1], c22 += cof[i] * u[i][1] * u[i][1];
  const double p11 = M.m11 * c11 + M.m12 * c12, p12 = M.m11 * c12 + M.m12 * c22;  // M C
  const double p21 = M.m12 * c11 + M.m22 * c12, p22 = M.m12 * c12 + M.m22 * c22;
  const double tr = p11 + p22, det = p11 * p22 - p12 * p21, disc = std::sqrt(std::max(0.0, tr * tr / 4 - det));
  const double l1 = tr / 2 + disc, l2 = tr / 2 - disc;
  auto extreme = [&](bool high) {
    double f = 0;
    for (double l : {l1, l2}) f += l * ((l > 0) == high ? gamma0 : 1 / gamma0);
    return f;
  };
  return extreme(false) < 0 && extreme(true) > 0;
}

}  // namespace anisocert::refiners::star
