#include "property_tests/generators/fields.hpp"

#include <rapidcheck.h>

#include <cmath>

namespace anisocert::gen {

predicates::Sym2<double> SmoothField::at(double x, double y) const {
  const double s = std::exp(cx * x + cy * y), t = theta0 + ax * x + ay * y, c = std::cos(t), n = std::sin(t);
  const double a = l1 * s, b = l2 * s;
  return {a * c * c + b * n * n, (a - b) * c * n, a * n * n + b * c * c};
}

fields::MetricField SmoothField::field() const {
  const SmoothField f = *this;
  return {"smooth random", {{"l1", l1}, {"l2", l2}, {"theta0", theta0}, {"ax", ax}, {"ay", ay}, {"cx", cx}, {"cy", cy}},
          [f](double x, double y) { return f.at(x, y); }};
}

SmoothField random_smooth_field() {
  const bool strong = *rc::gen::arbitrary<bool>();
  RC_TAG(strong ? "strong field" : "mild field");
  const int most = strong ? 400 : 100;
  const auto rate = [most] { return *rc::gen::inRange(-most, most + 1) / 100.0; };
  SmoothField f;
  f.l1 = *rc::gen::inRange(1, 101);
  f.l2 = f.l1 * (*rc::gen::inRange(10, strong ? 1001 : 101) / 10.0);
  f.theta0 = *rc::gen::inRange(0, 180) * M_PI / 180;
  f.ax = rate(), f.ay = rate(), f.cx = rate(), f.cy = rate();
  return f;
}

}  // namespace anisocert::gen
