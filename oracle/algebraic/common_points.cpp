#include "oracle/algebraic/common_points.hpp"

#include "oracle/algebraic/conic_intersection.hpp"
#include "oracle/algebraic/shared_line.hpp"

#include <algorithm>
#include <stdexcept>

namespace anisocert::oracle {
namespace {

bool inside(const AlgebraicPoint& p, const IntervalBox& box) {
  const auto within = [](const RealAlgebraic& v, const FilterInterval& range) {
    return compare(v, RealAlgebraic::rational(Rational(range.lo))) != Sign::negative &&
           compare(v, RealAlgebraic::rational(Rational(range.hi))) != Sign::positive;
  };
  return within(p.x(), box.x) && within(p.y(), box.y);
}

}  // namespace

CommonPoints exact_common_points(const Conic& A, const Conic& B, const Rational& width) {
  ++filter_context().counts.roots_exact;
  const ConicIntersection x = intersect(A, B);
  CommonPoints out;
  out.shared_component = x.shared_component;
  for (const IntersectionPoint& ip : x.points) out.points.emplace_back(ip.point, width);
  return out;
}

CommonPoints common_points(const CurvePair& curves, const IntervalBox& search, const Rational& width) {
  FilterContext& context = filter_context();
  const auto exact = [&] {
    const auto [A, B] = curves.exact();
    return exact_common_points(A, B, width);
  };
  if (context.exact_only) return exact();
  const auto boxes = certified_common_roots(curves.A, curves.B, search);
  if (!boxes) return exact();
  ++context.counts.roots_filtered;
  CommonPoints out;
  if (boxes->empty()) return out;
  const auto build = std::make_shared<const std::function<std::pair<Conic, Conic>()>>(curves.exact);  // shared by the recipes
  for (const IntervalBox& box : *boxes)
    // The box holds exactly one common point, and the other common points lie outside it.
    out.points.emplace_back(box, std::make_shared<const LocatedPoint::Recipe>([build, box] {
      // Isolated points only: the certified box's point is one, and curves that share a line
      // (which the exact intersection reports as a shared component) have some.
      const auto [A, B] = (*build)();
      for (const AlgebraicPoint& p : isolated_common_points(A, B))
        if (inside(p, box)) return p;
      throw std::logic_error("common_points: no exact common point in a certified box");
    }), build);
  std::sort(out.points.begin(), out.points.end(), [](const LocatedPoint& p, const LocatedPoint& q) {
    const Sign sx = compare_x(p, q);
    return sx != Sign::zero ? sx == Sign::negative : compare_y(p, q) == Sign::negative;
  });
  return out;
}

CommonPoints common_points(const Conic& A, const Conic& B, const IntervalBox& search, const Rational& width) {
  return common_points(CurvePair{IntervalConic::around(A), IntervalConic::around(B), [A, B] { return std::pair{A, B}; }},
                       search, width);
}

}  // namespace anisocert::oracle
