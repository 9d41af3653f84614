#pragma once
// The sites of a refinement run: their points, their metrics (sampled from the field once, when
// the site is inserted: LU §4, M_v = M(v)), and the grid that finds them.
#include "fields/metric_field.hpp"
#include "refiners/common/site_grid.hpp"

#include <vector>

namespace anisocert::refiners::common {

struct Sites {
  Sites(const Domain& domain, const fields::MetricField& f) : field(f), grid(domain.bounding_box()) {}

  // Adds q with its metric M = M(q) and files it in the grid (the caller rebuilds the grid when
  // outgrown).
  int add(const Point2<double>& q, const Sym2<double>& M) {
    const int k = static_cast<int>(points.size());
    points.push_back(q);
    metrics.push_back(M);
    grid.add(k, q);
    return k;
  }
  int add(const Point2<double>& q) { return add(q, field.at(q.x, q.y)); }
  std::size_t size() const { return points.size(); }
  const std::vector<int>& in(const Box& b) const { return grid.sites_in(b, points); }

  fields::MetricField field;
  std::vector<Point2<double>> points;
  std::vector<Sym2<double>> metrics;
  SiteGrid grid;
};

}  // namespace anisocert::refiners::common
