#pragma once
// The sites of a refinement run: their points, their metrics (sampled from the field once, when
// the site is inserted: LU §4, M_v = M(v)), and the grid that finds them.
#include "fields/metric_field.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/site_grid.hpp"

#include <cmath>

#include <vector>

namespace anisocert::refiners::common {

struct Sites {
  Sites(const Domain& domain, const fields::MetricField& f) : field(f), grid(domain.bounding_box()) {}

  // Adds q with its metric M = M(q) and files it in the grid (see grow_grid). Throws FieldError when M is not finite and positive definite (decided exactly:
  // m11 > 0 and m11 m22 − m12² > 0, the latter as an orientation determinant).
  int add(const Point2<double>& q, const Sym2<double>& M) {
    if (!(std::isfinite(M.m11) && std::isfinite(M.m12) && std::isfinite(M.m22) && M.m11 > 0 &&
          predicates::orientation<double>({0, 0}, {M.m11, M.m12}, {M.m12, M.m22}) == Sign::positive))
      throw FieldError("the metric field " + field.name + " is not finite and positive definite at " + point_text(q) + ": " +
                       metric_text(M));
    const int k = static_cast<int>(points.size());
    points.push_back(q);
    metrics.push_back(M);
    grid.add(k, q);
    return k;
  }
  int add(const Point2<double>& q) { return add(q, field.at(q.x, q.y)); }
  // Rebuilds the grid when the sites have outgrown it; true when it did (whoever files boxes in
  // the grid's cells then files them again).
  bool grow_grid() {
    if (!grid.outgrown(points.size())) return false;
    grid.rebuild(points);
    return true;
  }
  std::size_t size() const { return points.size(); }
  const std::vector<int>& in(const Box& b) const { return grid.sites_in(b, points); }

  fields::MetricField field;
  std::vector<Point2<double>> points;
  std::vector<Sym2<double>> metrics;
  SiteGrid grid;
};

}  // namespace anisocert::refiners::common
