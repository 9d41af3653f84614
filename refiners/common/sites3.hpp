#pragma once
// The sites of a 3D refinement run (issue 40), the twin of sites.hpp: points, metrics (the field's,
// sampled once when the site is inserted: LU §4, M_v = M(v)) and the grid that finds them.
#include "fields/metric_field.hpp"
#include "refiners/common/site_grid3.hpp"

#include <vector>

namespace anisocert::refiners::common {

// "[m11, m12, m13, m22, m23, m33]" (for messages).
std::string metric_text(const Sym3<double>& M);

struct Sites3 {
  Sites3(const Domain3& domain, const fields::MetricField3& f) : field(f), grid(domain.bounding_box()) {}

  // The field's metric at q; throws FieldError when it is not finite and positive definite
  // (decided exactly: the leading principal minors positive, predicates/metric.hpp).
  Sym3<double> metric_at(const Point3<double>& q) const;
  // Adds q with its metric and files it in the grid.
  int add(const Point3<double>& q, const Sym3<double>& M) {
    const int k = static_cast<int>(points.size());
    points.push_back(q);
    metrics.push_back(M);
    grid.add(k, q);
    return k;
  }
  // Rebuilds the grid when the sites have outgrown it; true when it did.
  bool grow_grid() {
    if (!grid.outgrown(points.size())) return false;
    grid.rebuild(points);
    return true;
  }
  std::size_t size() const { return points.size(); }
  const std::vector<int>& in(const Box3& b) const { return grid.sites_in(b, points); }
  // The sites within M-distance √reach2 of q (closed), by increasing index, in a buffer reused
  // across calls (see SiteGrid3::sites_in).
  const std::vector<int>& within(const Point3<double>& q, const Sym3<double>& M, double reach2) const;

  fields::MetricField3 field;
  std::vector<Point3<double>> points;
  std::vector<Sym3<double>> metrics;
  SiteGrid3 grid;

 private:
  mutable std::vector<int> found_;  // within's buffer
};

// The bounding box of the M-ball of squared radius r2 about c: half-widths √(r2 (M⁻¹)ᵢᵢ).
Box3 metric_ball_box(const Point3<double>& c, const Sym3<double>& M, double r2);

}  // namespace anisocert::refiners::common
