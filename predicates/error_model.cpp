#include "predicates/error_model.hpp"

#include <cmath>

namespace anisocert::predicates {
namespace {
constexpr double u = 0x1p-53;
}

ErrorModel::ErrorModel(double constant) {
  if (constant != 0) terms_.push_back({Multidegree{}, std::fabs(constant), 0.0});
}

ErrorModel ErrorModel::leaf(int group) {
  ErrorModel e;
  Multidegree d{};
  d[group] = 1;
  e.terms_.push_back({d, 1.0, 0.0});
  return e;
}

void ErrorModel::add(const Monomial& m) {
  for (Monomial& t : terms_)
    if (t.degree == m.degree) {
      t.mag += m.mag;
      t.err += m.err;
      return;
    }
  terms_.push_back(m);
}

ErrorModel operator+(const ErrorModel& a, const ErrorModel& b) {
  ErrorModel r;
  for (const auto& t : a.terms_) r.add(t);
  for (const auto& t : b.terms_) r.add(t);
  // The sum's own rounding: u times a bound on its computed magnitude, spread per monomial.
  for (auto& t : r.terms_) t.err += u * (t.mag + t.err);
  return r;
}

ErrorModel operator-(const ErrorModel& a) { return a; }  // magnitudes and errors are unsigned

ErrorModel operator-(const ErrorModel& a, const ErrorModel& b) { return a + b; }

ErrorModel operator*(const ErrorModel& a, const ErrorModel& b) {
  ErrorModel r;
  for (const auto& x : a.terms_)
    for (const auto& y : b.terms_) {
      Multidegree d{};
      for (int g = 0; g < magnitude_groups; ++g) d[g] = x.degree[g] + y.degree[g];
      r.add({d, x.mag * y.mag,
             x.err * y.mag + x.mag * y.err + x.err * y.err + u * (x.mag + x.err) * (y.mag + y.err)});
    }
  return r;
}

}  // namespace anisocert::predicates
