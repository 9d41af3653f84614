#include "refiners/star/metric_field.hpp"

#include <cmath>
#include <stdexcept>

namespace anisocert::refiners::star {

using predicates::Sym2;

namespace {

// ((1 + α s)/h)² n nᵀ + (1/h)² (I − n nᵀ) for a unit vector n.
Sym2<double> stretched(double nx, double ny, double s, double h, double alpha) {
  const double across = std::pow((1 + alpha * s) / h, 2), along = 1 / (h * h);
  return {across * nx * nx + along * ny * ny, (across - along) * nx * ny, across * ny * ny + along * nx * nx};
}

double sech2(double u) {
  const double c = std::cosh(u);
  return std::isfinite(c) ? 1 / (c * c) : 0;
}

}  // namespace

std::vector<std::string> field_names() { return {"constant", "linear", "shock", "radial"}; }

MetricField make_field(const std::string& name, const std::map<std::string, double>& given) {
  std::map<std::string, double> p;
  if (name == "constant") p = {{"m11", 1}, {"m12", 0}, {"m22", 1}};
  else if (name == "linear") p = {{"hx", 0.1}, {"h0", 1e-3}};
  else if (name == "shock") p = {{"delta", 0.6}, {"h", 0.05}, {"alpha", 9}};
  else if (name == "radial") p = {{"cx", 0.5}, {"cy", 0.5}, {"R", 0.25}, {"delta", 0.05}, {"h", 0.05}, {"alpha", 9}};
  else throw std::invalid_argument("unknown field \"" + name + "\" (constant, linear, shock, radial)");
  for (const auto& [k, v] : given) {
    if (!p.count(k)) throw std::invalid_argument("field " + name + " has no parameter \"" + k + "\"");
    if (!std::isfinite(v)) throw std::invalid_argument("parameter " + k + " must be finite");
    p[k] = v;
  }
  auto positive = [&](const char* k) {
    if (!(p[k] > 0)) throw std::invalid_argument("parameter " + std::string(k) + " of field " + name + " must be positive");
  };
  MetricField f{name, p, {}};
  if (name == "constant") {
    const double a = p["m11"], b = p["m12"], c = p["m22"];
    if (!(a > 0 && a * c - b * b > 0)) throw std::invalid_argument("field constant: [m11 m12; m12 m22] must be positive definite");
    f.at = [a, b, c](double, double) { return Sym2<double>{a, b, c}; };
  } else if (name == "linear") {
    positive("hx"), positive("h0");
    const double hx = p["hx"], h0 = p["h0"];
    f.at = [hx, h0](double, double y) {
      const double hy = h0 + 2 * (hx - h0) * std::abs(y - 0.5);
      return Sym2<double>{1 / (hx * hx), 0, 1 / (hy * hy)};
    };
  } else if (name == "shock") {
    positive("delta"), positive("h");
    const double d = p["delta"], h = p["h"], alpha = p["alpha"];
    if (alpha < 0) throw std::invalid_argument("parameter alpha of field shock must be >= 0");
    f.at = [d, h, alpha](double x, double y) {
      const double gx = 2, gy = -5 * std::cos(5 * y), g = std::hypot(gx, gy);
      return stretched(gx / g, gy / g, sech2((2 * x - std::sin(5 * y)) / d), h, alpha);
    };
  } else {
    positive("delta"), positive("h"), positive("R");
    const double cx = p["cx"], cy = p["cy"], R = p["R"], d = p["delta"], h = p["h"], alpha = p["alpha"];
    if (alpha < 0) throw std::invalid_argument("parameter alpha of field radial must be >= 0");
    f.at = [cx, cy, R, d, h, alpha](double x, double y) {
      const double r = std::hypot(x - cx, y - cy);
      const double nx = r > 0 ? (x - cx) / r : 1, ny = r > 0 ? (y - cy) / r : 0;
      return stretched(nx, ny, sech2((r - R) / d), h, alpha);
    };
  }
  return f;
}

}  // namespace anisocert::refiners::star
