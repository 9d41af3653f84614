// The angles of each triangle in its corners' metrics against a lower bound (metric_checks.hpp).
#include "oracle/certify/metric_checks.hpp"

#include "numbers/interval.hpp"
#include "predicates/angle.hpp"
#include "predicates/metric_dot.hpp"

#include <cmath>
#include <numbers>

namespace anisocert::oracle {

std::pair<Rational, Rational> sin_squared_bounds(const Rational& degrees, long prec) {
  // θ in (0°, 90°] at a multiple of 30° or 45°: sin² θ ∈ {1/4, 1/2, 3/4, 1}, rational.
  const std::pair<int, Rational> exact[] = {{30, Rational(1, 4)}, {45, Rational(1, 2)}, {60, Rational(3, 4)}, {90, 1}};
  for (const auto& [d, s] : exact)
    if (degrees == d) return {s, s};
  const Interval s = sin(radians(Interval(degrees, prec)));
  const Interval s2 = sqr(s);
  Rational lo, hi;
  mpfr_get_q(lo.backend().data(), s2.lower());
  mpfr_get_q(hi.backend().data(), s2.upper());
  return {lo, hi};
}

namespace {

// The corner at b of triangle abc measured by M_b: its angle (approximate, degrees) and sign
// decisions on the enclosures first.
class Corner {
 public:
  Corner(const EnclosedMesh& m, int a, int b, int c) : m_(m), a_(a), b_(b), c_(c) {}

  double approx_degrees() const {
    const auto in = enclosure(FilterInterval(0));
    const auto [dot, norms] = predicates::angle_dot_and_norms(in);
    const double d = (dot.lo + dot.hi) / 2, n = std::sqrt(std::max(0.0, (norms.lo + norms.hi) / 2));
    return n > 0 ? std::acos(std::clamp(d / n, -1.0, 1.0)) * 180 / std::numbers::pi : 0;
  }
  bool obtuse_or_right() const {  // uᵀMw <= 0: the angle is at least 90°
    const auto e = enclosure(FilterInterval(0));
    return predicates::interval_then_exact<predicates::MetricDotKernel>(
               std::array<FilterInterval, 9>{e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]}, [&] {
                 const auto x = exact(0);
                 return std::array<Rational, 9>{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8]};
               }) != Sign::positive;
  }
  // sign(s − sin² angle) for an acute angle: positive when the angle is below arcsin √s.
  Sign below(const Rational& s) const {
    return predicates::interval_then_exact<predicates::AngleSinKernel>(enclosure(enclose(s)), [&] { return exact(s); });
  }

 private:
  std::array<FilterInterval, 10> enclosure(const FilterInterval& s) const {
    const auto &a = m_.site[a_], &b = m_.site[b_], &c = m_.site[c_];
    const auto& M = m_.metric[b_];
    return {a.x, a.y, b.x, b.y, c.x, c.y, M.m11, M.m12, M.m22, s};
  }
  std::array<Rational, 10> exact(const Rational& s) const {
    const auto& p = m_.mesh.sites;
    const auto& n = m_.mesh.metrics;
    return {p[a_].x, p[a_].y, p[b_].x, p[b_].y, p[c_].x, p[c_].y, n[b_].m11, n[b_].m12, n[b_].m22, s};
  }
  const EnclosedMesh& m_;
  int a_, b_, c_;
};

}  // namespace

AngleReport check_angles(const EnclosedMesh& m, const std::optional<Rational>& min_angle, std::size_t described) {
  AngleReport r;
  r.violations = WitnessList(described);
  const auto& tris = m.mesh.triangles;
  std::pair<Rational, Rational> bounds;
  if (min_angle) bounds = sin_squared_bounds(*min_angle, 128);
  std::vector<std::pair<int, int>> open;  // (triangle, corner) that the bounds did not decide
  for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
    const auto& tri = tris[t];
    if (m.orientation(tri[0], tri[1], tri[2]) != Sign::positive) {  // flat or clockwise: validity reports it
      ++r.undecided;
      continue;
    }
    ++r.measured;
    bool reported = false;
    for (int i = 0; i < 3; ++i) {
      const Corner corner(m, tri[(i + 2) % 3], tri[i], tri[(i + 1) % 3]);
      const double deg = corner.approx_degrees();
      if (deg < r.smallest) r.smallest = deg, r.smallest_triangle = t;
      if (!min_angle || reported || corner.obtuse_or_right() || corner.below(bounds.second) != Sign::positive) continue;
      if (corner.below(bounds.first) == Sign::positive) {
        reported = true;
        r.violations.add(tri[i], t, -1, [&] {
          return "triangle " + std::to_string(t) + " has an angle of about " + std::to_string(deg) + "° at vertex " +
                 std::to_string(tri[i]) + " in that vertex's metric, below the bound";
        });
      } else {
        open.emplace_back(t, i);
      }
    }
  }
  // sin² θ irrational and a corner within the enclosure: refine it (the rational sin² of the corner
  // differs from sin² θ, so some precision decides it).
  std::vector<bool> reported(tris.size(), false);
  for (const WitnessPlace& w : r.violations.places()) reported[w.triangle] = true;
  for (long prec = 256; !open.empty() && prec <= 8192; prec *= 2) {
    bounds = sin_squared_bounds(*min_angle, prec);
    std::vector<std::pair<int, int>> still;
    for (const auto& corner_at : open) {
      const int t = corner_at.first, i = corner_at.second;  // named, not bound: clang 14 cannot capture bindings
      const auto& tri = tris[t];
      const Corner corner(m, tri[(i + 2) % 3], tri[i], tri[(i + 1) % 3]);
      if (reported[t] || corner.below(bounds.second) != Sign::positive) continue;
      if (corner.below(bounds.first) == Sign::positive)
        reported[t] = true, r.violations.add(tri[i], t, -1, [&] {
          return "triangle " + std::to_string(t) + " has an angle below the bound at vertex " + std::to_string(tri[i]) +
                 " in that vertex's metric";
        });
      else
        still.emplace_back(t, i);
    }
    open = std::move(still);
  }
  for (const auto& [t, i] : open) r.undecided_triangles.push_back(t);
  return r;
}

}  // namespace anisocert::oracle
