// The angles of each triangle in its corners' metrics, and the dihedral angles of each tetrahedron in
// its edges' ends' metrics, against a lower bound (metric_checks.hpp): one loop, a level per dimension.
#include "oracle/certify/metric_checks.hpp"

#include "numbers/interval.hpp"
#include "predicates/angle.hpp"
#include "predicates/dihedral.hpp"
#include "predicates/metric_dot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

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

// The cosine dot / √norms (approximate, in [−1, 1]); 1 (an angle of 0°) when the norms vanish.
double cosine_of(double dot, double norms) {
  const double n = std::sqrt(std::max(0.0, norms));
  return n > 0 ? std::clamp(dot / n, -1.0, 1.0) : 1;
}
double cosine_of(const FilterInterval& dot, const FilterInterval& norms) { return cosine_of((dot.lo + dot.hi) / 2, (norms.lo + norms.hi) / 2); }
// The angle of a cosine, in degrees: asked once per element (angles are compared by cosine).
double degrees_of(double cosine) { return std::acos(cosine) * 180 / std::numbers::pi; }

// The corner at b of triangle abc measured by M_b: its angle (approximate, degrees) and sign
// decisions on the enclosures first.
class Corner {
 public:
  Corner(const EnclosedMesh& m, int a, int b, int c) : m_(m), a_(a), b_(b), c_(c) {}

  double approx_cosine() const {
    const auto in = enclosure(FilterInterval(0));
    const auto [dot, norms] = predicates::angle_dot_and_norms(in);
    return cosine_of(dot, norms);
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
  int vertex() const { return b_; }
  std::string where() const { return "at vertex " + std::to_string(b_) + " in that vertex's metric"; }

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

// The dihedral angle of tetrahedron abcd at edge ab (between faces abc and abd) measured by the
// metric of `by`, a or b (predicates/dihedral.hpp).
class Dihedral {
 public:
  Dihedral(const EnclosedMesh3& m, int a, int b, int c, int d, int by) : m_(m), v_{a, b, c, d}, by_(by) {}

  // In doubles (the angle reported is approximate; decisions are below): the points' nearest
  // doubles and the metric enclosures' midpoints.
  double approx_cosine() const {
    std::array<double, 18> x;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& p = m_.approx[static_cast<std::size_t>(v_[i])];
      x[3 * i] = p.x, x[3 * i + 1] = p.y, x[3 * i + 2] = p.z;
    }
    const auto& M = m_.metric[static_cast<std::size_t>(by_)];
    std::size_t k = 12;
    for (const FilterInterval* e : {&M.m11, &M.m12, &M.m13, &M.m22, &M.m23, &M.m33}) x[k++] = e->lo / 2 + e->hi / 2;
    const auto [dot, norms] = predicates::dihedral_dot_and_norms(x);
    return cosine_of(dot, norms);
  }
  bool obtuse_or_right() const {
    const auto e = enclosure(FilterInterval(0));
    if (m_.doubles(v_, by_)) {  // the double evaluation checked for rounding decides a right angle's exact 0
      std::array<double, 18> x;
      for (std::size_t i = 0; i < 18; ++i) x[i] = e[i].lo;
      return predicates::filtered_sign<predicates::DihedralDotKernel>(x) != Sign::positive;
    }
    std::array<FilterInterval, 18> head;
    std::copy_n(e.begin(), 18, head.begin());
    return predicates::interval_then_exact<predicates::DihedralDotKernel>(head, [&] {
             const auto x = exact(0);
             std::array<Rational, 18> h;
             std::copy_n(x.begin(), 18, h.begin());
             return h;
           }) != Sign::positive;
  }
  Sign below(const Rational& s) const {
    return predicates::interval_then_exact<predicates::DihedralSinKernel>(enclosure(enclose(s)), [&] { return exact(s); });
  }
  int vertex() const { return by_; }
  std::string where() const {
    return "at edge " + std::to_string(v_[0]) + "–" + std::to_string(v_[1]) + " in the metric of vertex " + std::to_string(by_);
  }

 private:
  std::array<FilterInterval, 19> enclosure(const FilterInterval& s) const {
    std::array<FilterInterval, 19> x;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& p = m_.vertex[static_cast<std::size_t>(v_[i])];
      x[3 * i] = p.x, x[3 * i + 1] = p.y, x[3 * i + 2] = p.z;
    }
    const auto& M = m_.metric[static_cast<std::size_t>(by_)];
    x[12] = M.m11, x[13] = M.m12, x[14] = M.m13, x[15] = M.m22, x[16] = M.m23, x[17] = M.m33, x[18] = s;
    return x;
  }
  std::array<Rational, 19> exact(const Rational& s) const {
    std::array<Rational, 19> x;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& p = m_.mesh.vertices[static_cast<std::size_t>(v_[i])];
      x[3 * i] = p.x, x[3 * i + 1] = p.y, x[3 * i + 2] = p.z;
    }
    const auto& M = m_.mesh.metrics[static_cast<std::size_t>(by_)];
    x[12] = M.m11, x[13] = M.m12, x[14] = M.m13, x[15] = M.m22, x[16] = M.m23, x[17] = M.m33, x[18] = s;
    return x;
  }
  const EnclosedMesh3& m_;
  std::array<int, 4> v_;
  int by_;
};

// Per dimension, what the one loop below asks of an element: whether it is measured (a flat or
// clockwise triangle, a flat tetrahedron: validity reports it) and its angles.
struct Triangles {
  static constexpr const char* element = "triangle";
  static constexpr const char* kind = "an angle";
  static constexpr bool unmeasured_fails = false;  // flat or clockwise: `valid` fails it
  const EnclosedMesh& m;
  std::size_t size() const { return m.mesh.triangles.size(); }
  bool measurable(std::size_t t) const {
    const auto& tri = m.mesh.triangles[t];
    return m.orientation(tri[0], tri[1], tri[2]) == Sign::positive;
  }
  static constexpr std::size_t angles = 3;
  bool repeats(std::size_t, std::size_t) const { return false; }
  Corner angle(std::size_t t, std::size_t i) const {
    const auto& tri = m.mesh.triangles[t];
    return Corner(m, tri[(i + 2) % 3], tri[i], tri[(i + 1) % 3]);
  }
};

// Each of the six edges' dihedral angles, in each end's metric.
struct Tetrahedra {
  static constexpr const char* element = "tetrahedron";
  static constexpr const char* kind = "a dihedral angle";
  static constexpr bool unmeasured_fails = true;   // flat: angles 0° and 180°, below any bound
  const EnclosedMesh3& m;
  std::size_t size() const { return m.mesh.tetrahedra.size(); }
  bool measurable(std::size_t t) const {
    return m.orientation(t) != Sign::zero;
  }
  static constexpr std::size_t angles = 12;
  static constexpr std::array<std::array<int, 4>, 6> edges{{{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}}};
  // The angle in the edge's second end's metric when it equals the first's (a constant field).
  bool repeats(std::size_t t, std::size_t k) const {
    if (k % 2 == 0) return false;
    const auto& v = m.mesh.tetrahedra[t];
    const auto& e = edges[k / 2];
    return m.same_metric(v[static_cast<std::size_t>(e[0])], v[static_cast<std::size_t>(e[1])]);
  }
  Dihedral angle(std::size_t t, std::size_t k) const {
    const auto& v = m.mesh.tetrahedra[t];
    const auto& e = edges[k / 2];
    const auto at = [&](int i) { return v[static_cast<std::size_t>(i)]; };
    return Dihedral(m, at(e[0]), at(e[1]), at(e[2]), at(e[3]), k % 2 ? at(e[1]) : at(e[0]));
  }
};

template <class Level>
AngleReport check_angles_of(const Level& level, const std::optional<Rational>& min_angle, std::size_t described) {
  AngleReport r;
  r.violations = WitnessList(described);
  std::pair<Rational, Rational> bounds;
  if (min_angle) bounds = sin_squared_bounds(*min_angle, 128);
  std::vector<std::pair<std::size_t, std::size_t>> open;  // (element, angle) that the bounds did not decide
  const auto report = [&](std::size_t t, const auto& angle, const std::string& about) {
    r.violations.add(angle.vertex(), static_cast<int>(t), -1, [&] {
      return std::string(Level::element) + " " + std::to_string(t) + " has " + Level::kind + about + " " + angle.where() + ", below the bound";
    });
  };
  // The extremes by cosine (a smaller angle has a larger cosine), in degrees at the end.
  double smallest = -1, largest = 1;
  for (std::size_t t = 0; t < level.size(); ++t) {
    if (!level.measurable(t)) {
      ++r.undecided;
      if constexpr (Level::unmeasured_fails)  // a flat tetrahedron's dihedral angles are 0° and 180°
        if (min_angle)
          r.violations.add(level.m.mesh.tetrahedra[t][0], static_cast<int>(t), -1,
                           [&] { return std::string(Level::element) + " " + std::to_string(t) + " is flat: its dihedral angles are 0° and 180°"; });
      continue;
    }
    ++r.measured;
    bool reported = false;
    double least = -1;
    for (std::size_t i = 0; i < Level::angles; ++i) {
      if (level.repeats(t, i)) continue;
      const auto angle = level.angle(t, i);
      const double cosine = angle.approx_cosine();
      least = std::max(least, cosine);
      if (cosine > smallest) smallest = cosine, r.smallest_triangle = static_cast<int>(t);
      if (cosine < largest) largest = cosine, r.largest_triangle = static_cast<int>(t);
      if (!min_angle || reported || angle.obtuse_or_right() || angle.below(bounds.second) != Sign::positive) continue;
      if (angle.below(bounds.first) == Sign::positive) {
        reported = true;
        report(t, angle, " of about " + std::to_string(degrees_of(cosine)) + "°");
      } else {
        open.emplace_back(t, i);
      }
    }
    r.element_smallest.push_back(degrees_of(least));
  }
  if (r.smallest_triangle >= 0) r.smallest = degrees_of(smallest);
  if (r.largest_triangle >= 0) r.largest = degrees_of(largest);
  // sin² θ irrational and an angle within the enclosure: refine it (the angle's rational sin²
  // differs from sin² θ, so some precision decides it).
  std::vector<bool> reported(level.size(), false);
  for (const WitnessPlace& w : r.violations.places()) reported[static_cast<std::size_t>(w.triangle)] = true;
  for (long prec = 256; !open.empty() && prec <= 8192; prec *= 2) {
    bounds = sin_squared_bounds(*min_angle, prec);
    std::vector<std::pair<std::size_t, std::size_t>> still;
    for (const auto& at : open) {
      const std::size_t t = at.first;  // named, not bound: clang 14 cannot capture bindings
      const auto angle = level.angle(t, at.second);
      if (reported[t] || angle.below(bounds.second) != Sign::positive) continue;
      if (angle.below(bounds.first) == Sign::positive) reported[t] = true, report(t, angle, "");
      else still.push_back(at);
    }
    open = std::move(still);
  }
  for (const auto& at : open) r.undecided_triangles.push_back(static_cast<int>(at.first));
  return r;
}

}  // namespace

AngleReport check_angles(const EnclosedMesh& m, const std::optional<Rational>& min_angle, std::size_t described) {
  return check_angles_of(Triangles{m}, min_angle, described);
}

AngleReport check_angles(const EnclosedMesh3& m, const std::optional<Rational>& min_angle, std::size_t described) {
  return check_angles_of(Tetrahedra{m}, min_angle, described);
}

}  // namespace anisocert::oracle
