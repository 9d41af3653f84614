#include "fields/normalized.hpp"

#include <cmath>

namespace anisocert::fields {

predicates::Sym2<double> normalized(const predicates::Sym2<double>& M) {
  // Kahan: m11 m22 − m12² with the rounding error of m12² recovered by an fma.
  const double w = M.m12 * M.m12;
  const double det = std::fma(M.m11, M.m22, -w) + std::fma(-M.m12, M.m12, w);
  if (!(det > 0 && M.m11 > 0 && std::isfinite(det))) return M;
  const double s = 1 / std::sqrt(det);
  return {s * M.m11, s * M.m12, s * M.m22};
}

MetricField normalized(const MetricField& f) {
  return {"normalized " + f.name, f.params, [at = f.at](double x, double y) { return normalized(at(x, y)); }};
}

}  // namespace anisocert::fields
