// Edge lengths in the endpoints' metrics (metric_checks.hpp), each comparison exact; one loop for
// triangle and tetrahedral meshes, a kernel per dimension.
#include "oracle/certify/metric_checks.hpp"

#include "predicates/filtered_sign.hpp"
#include "predicates/point.hpp"

#include <cmath>
#include <type_traits>

namespace anisocert::oracle {
namespace {

// ℓ² − c for ℓ² = (b − a)ᵀ M (b − a): inputs a, b, M, c (in the plane and in space).
struct LengthKernel {
  static constexpr std::size_t arity = 8;
  template <class T>
  static T eval(const std::array<T, arity>& x) {
    return predicates::quadratic_form(x[4], x[5], x[6], T(x[2] - x[0]), T(x[3] - x[1])) - x[7];
  }
};
struct Length3Kernel {
  static constexpr std::size_t arity = 13;
  static constexpr std::array<int, arity> groups{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 2};
  template <class T>
  static constexpr T eval(const std::array<T, arity>& x) {
    return predicates::quadratic_form(x[6], x[7], x[8], x[9], x[10], x[11], T(x[3] - x[0]), T(x[4] - x[1]), T(x[5] - x[2])) - x[12];
  }
};

// The kernel's inputs for edge ab in the metric of v with bound c, from a mesh's points and metrics
// (exact numbers or their enclosures).
template <class P, class M, class C>
std::array<C, 8> inputs(const P& a, const P& b, const M& m, const C& c) requires requires { a.y; } && (!requires { a.z; }) {
  return {a.x, a.y, b.x, b.y, m.m11, m.m12, m.m22, c};
}
template <class P, class M, class C>
std::array<C, 13> inputs(const P& a, const P& b, const M& m, const C& c) requires requires { a.z; } {
  return {a.x, a.y, a.z, b.x, b.y, b.z, m.m11, m.m12, m.m13, m.m22, m.m23, m.m33, c};
}

// The points and metrics of either enclosed mesh.
const auto& points(const EnclosedMesh& m) { return m.site; }
const auto& points(const EnclosedMesh3& m) { return m.vertex; }
const auto& exact_points(const EnclosedMesh& m) { return m.mesh.sites; }
const auto& exact_points(const EnclosedMesh3& m) { return m.mesh.vertices; }
const auto& exact_metrics(const EnclosedMesh& m) { return m.mesh.metrics; }
const auto& exact_metrics(const EnclosedMesh3& m) { return m.mesh.metrics; }

// The length² of edge ab in the metric of v, enclosed once; each comparison with a bound c is
// read off the enclosure when c lies outside it, else decided exactly.
template <class Enclosed, class Kernel>
class Length2 {
 public:
  Length2(const Enclosed& m, int a, int b, int v) : m_(m), a_(a), b_(b), v_(v), l2_(enclosure()) {}
  // sign(ℓ² − c), ci enclosing c
  Sign compare(const Rational& c, const FilterInterval& ci) const {
    if (l2_.lo > ci.hi) return Sign::positive;
    if (l2_.hi < ci.lo) return Sign::negative;
    return predicates::exact_sign<Kernel>(inputs(exact_points(m_)[a_], exact_points(m_)[b_], exact_metrics(m_)[v_], c));
  }
  double approx() const { return std::sqrt(std::max(0.0, (l2_.lo + l2_.hi) / 2)); }

 private:
  // The static bound when every input is a double (a tetrahedral mesh's from a binary file), else
  // intervals.
  FilterInterval enclosure() const {
    const auto& p = points(m_);
    const auto& M = m_.metric;
    if constexpr (std::is_same_v<Enclosed, EnclosedMesh3>) {
      if (m_.doubles(std::array<int, 2>{a_, b_}, v_)) {
        const auto x = inputs(m_.approx[a_], m_.approx[b_], predicates::Sym3<double>{M[v_].m11.lo, M[v_].m12.lo, M[v_].m13.lo, M[v_].m22.lo, M[v_].m23.lo, M[v_].m33.lo}, 0.0);
        if (const auto l2 = predicates::static_enclosure<Kernel>(x)) return *l2;
      }
    }
    return Kernel::template eval<FilterInterval>(inputs(p[a_], p[b_], M[v_], FilterInterval(0)));
  }

  const Enclosed& m_;
  int a_, b_, v_;
  FilterInterval l2_;
};

template <class Kernel, class Enclosed>
LengthReport lengths(const Enclosed& m, const std::vector<std::pair<int, int>>& edges,
                     const std::optional<std::pair<Rational, Rational>>& range, std::size_t described) {
  LengthReport r;
  r.range_violations = WitnessList(described);
  const Rational half(1, 2), two(2);
  const FilterInterval half_i(0.5), two_i(2.0);
  std::optional<std::pair<Rational, Rational>> range2;
  std::pair<FilterInterval, FilterInterval> range2_i;
  if (range) {
    range2 = std::pair(range->first * range->first, range->second * range->second);
    range2_i = {enclose(range2->first), enclose(range2->second)};
  }
  r.edges = edges.size();
  r.lengths.reserve(2 * edges.size());
  r.shortest = INFINITY;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const int a = edges[k].first, b = edges[k].second;  // named, not bound: clang 14 cannot capture bindings
    bool unit = true, reported = false;
    for (const int v : {a, b}) {
      const Length2<Enclosed, Kernel> l2(m, a, b, v);
      unit = unit && l2.compare(half, half_i) != Sign::negative && l2.compare(two, two_i) != Sign::positive;
      const double l = l2.approx();
      r.lengths.push_back(l);
      if (l < r.shortest) r.shortest = l, r.shortest_edge = static_cast<int>(k);
      if (l > r.longest) r.longest = l, r.longest_edge = static_cast<int>(k);
      if (range2 && !reported &&
          (l2.compare(range2->first, range2_i.first) == Sign::negative ||
           l2.compare(range2->second, range2_i.second) == Sign::positive)) {
        reported = true;
        r.range_violations.add(v, -1, v == a ? b : a, [&] {
          return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ") has length " + std::to_string(l) +
                 " in the metric of vertex " + std::to_string(v) + ", outside the range";
        });
      }
    }
    r.unit_edges += unit;
  }
  if (edges.empty()) r.shortest = 0;
  return r;
}

}  // namespace

LengthReport check_lengths(const EnclosedMesh& m, const std::vector<std::pair<int, int>>& edges,
                           const std::optional<std::pair<Rational, Rational>>& range, std::size_t described) {
  return lengths<LengthKernel>(m, edges, range, described);
}

LengthReport check_lengths(const EnclosedMesh3& m, const std::vector<std::pair<int, int>>& edges,
                           const std::optional<std::pair<Rational, Rational>>& range, std::size_t described) {
  return lengths<Length3Kernel>(m, edges, range, described);
}

}  // namespace anisocert::oracle
