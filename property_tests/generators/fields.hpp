#pragma once
// A RapidCheck generator of smooth random metric fields: eigenvalues λ₁ e^{c·x}, λ₂ e^{c·x}, axes
// turning by θ₀ + a·x, with λ₁ in [1, 100] and rates drawn per unit length. "mild": rates up to 1,
// axis ratio up to 10; "strong": rates up to 4, ratio up to 100, where bisectors of neighbours are
// small ellipses, and islands and orphans are common (tagged).
#include "fields/metric_field.hpp"

namespace anisocert::gen {

struct SmoothField {
  double l1, l2, theta0, ax, ay, cx, cy;
  predicates::Sym2<double> at(double x, double y) const;
  fields::MetricField field() const;  // named "smooth random", for the refiners
};

SmoothField random_smooth_field();

}  // namespace anisocert::gen
