#include "predicates/filtered_sign.hpp"

namespace anisocert::predicates {

FilterStats& filter_stats() {
  thread_local FilterStats stats;
  return stats;
}

bool in_static_range(const std::array<double, magnitude_groups>& max) {
  for (double m : max)
    if (m != 0 && !(m >= 0x1p-50 && m <= 0x1p50)) return false;
  return true;
}

double static_error_bound(const ErrorModel& model, const std::array<double, magnitude_groups>& max) {
  double bound = 0;
  for (const ErrorModel::Monomial& t : model.monomials()) {
    double term = t.err;
    for (int g = 0; g < magnitude_groups; ++g)
      for (int k = 0; k < t.degree[g]; ++k) term *= max[g];
    bound += term;
  }
  return bound * (1 + 0x1p-40) + 0x1p-600;
}

}  // namespace anisocert::predicates
