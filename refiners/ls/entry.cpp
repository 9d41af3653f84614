#include "refiners/ls/entry.hpp"

#include "refiners/common/summary.hpp"
#include "refiners/ls/ls_refiner.hpp"
#include "refiners/ls/theorem11_conditions.hpp"

#include <cmath>
#include <sstream>

namespace anisocert::refiners::ls {
namespace {

LsParameters parameters(const ParameterValues& v, const common::Budget& budget) {
  LsParameters p;
  static_cast<common::Budget&>(p) = budget;
  p.theta_bound = v.at("theta-bound"), p.size = v.at("size");
  p.off_centres = v.at("off-centres") != 0;
  p.normalized_metric = v.at("normalized-metric") != 0;
  if (!(p.theta_bound > 0 && p.theta_bound < 60))
    throw ParameterError("--theta-bound " + shortest_decimal(p.theta_bound) + " is out of range: need 0 < θ_bound < 60 (degrees)");
  if (!(p.size >= 0 && std::isfinite(p.size)))
    throw ParameterError("--size " + shortest_decimal(p.size) + " is out of range: need 0 <= size < ∞ (0: no size rule)");
  return p;
}

std::string corner_list(const std::vector<int>& corners) {
  std::string s;
  for (int k : corners) s += " " + std::to_string(k);
  return s;
}

std::vector<std::string> report(const LsResult& r, const LsParameters& p, const common::Domain& domain, bool one_metric) {
  std::vector<std::string> lines{
      common::size_line(r, "LS refiner"),
      common::stop_line(r, r.left_counted ? "encroached subsegments: " + std::to_string(r.encroached_left) +
                                                ", violators: " + std::to_string(r.violators_left)
                                          : "encroached subsegments and violators not counted (the time budget is spent)")};
  std::vector<predicates::Sym2<double>> metrics(r.mesh.metrics.begin(), r.mesh.metrics.begin() + static_cast<long>(domain.vertices().size()));
  const Theorem11Conditions c = theorem11_conditions(domain, metrics, p.theta_bound);
  std::ostringstream o;
  o << "  LS Theorem 11 (decided exactly): ";
  if (!c.theta_admissible) {
    o << "θ_bound = " << p.theta_bound << "° is not below arcsin(1/(2√2)) ≈ 20.7°: no termination guarantee";
  } else {
    o.precision(10);
    o << "θ_bound admissible, γ(θ_bound) ∈ [" << c.gamma_lo << ", " << c.gamma_hi << "]; adjoining segments need ";
    o.precision(6);
    const std::string where = domain.has_interior() ? "vertex" : "corner";  // X's vertices: the corners, then the points
    o << c.separation_hi << "° (2 arcsin(γ²/2)) in the " << where << "'s metric: ";
    if (c.corners_failing.empty() && c.corners_undecided.empty()) o << "holds at every " << where;
    if (!c.corners_failing.empty()) o << "fails at " << where << "(s)" << corner_list(c.corners_failing);
    if (!c.corners_undecided.empty())
      o << (c.corners_failing.empty() ? "" : "; ") << "undecided at " << where << "(s)" << corner_list(c.corners_undecided);
    if (p.size > 0) o << "; the theorem assumes no size rule (it applies with --size 0)";
  }
  lines.push_back(o.str());
  lines.push_back(common::rule_counts_line(r));
  if (r.exempt_left > 0)
    lines.push_back("  left with a poor angle at small input angles: " + std::to_string(r.exempt_left) +
                    " triangles across two segments that meet at less than 60° in the metric (their shortest edge joins the "
                    "two on one shell; rule 3 leaves them: docs/refiners.md § Concentric shells at sharp corners)");
  lines.push_back(!one_metric ? "  angles checked in the metrics of the triangle's three vertices and of the field at its Voronoi vertex rounded to doubles "
                                   "(LS: every point of the triangle)"
                                 : "  angles checked in the metric of the triangle's vertices and of its Voronoi vertex (one metric: LS checks every point of the triangle)");
  o.str("");
  o << "  parameters: θ_bound = " << p.theta_bound << "°, size = " << p.size << (p.size > 0 ? "" : " (no size rule)")
    << (p.off_centres ? ", off-centres" : "");
  lines.push_back(o.str());
  if (p.normalized_metric)
    lines.push_back("  normalized metric (LS §9): the diagram, the angles and the mesh's metrics in M′ = det(M)^(−1/2) M rounded to doubles; "
                    "sizes in the field's M at each of the triangle's vertices");
  return lines;
}

}  // namespace

RefinerEntry entry() {
  const LsParameters d;
  return {"ls",
          "Labelle–Shewchuk Voronoi refinement (LS §9: encroached segments, then Voronoi vertices whose dual triangle has an "
          "angle below θ_bound or is too large, inverted or unwedged); the constant field on Del_M, other fields on the true "
          "diagram of sites with different metrics",
          {{"theta-bound", "smallest angle θ_bound in degrees (LS Theorem 11 needs θ_bound < arcsin(1/(2√2)) ≈ 20.7048°)", d.theta_bound},
           {"size", "largest circumradius in the metric, 0 for none", d.size},
           {"normalized-metric",
            "LS §9's variation: the diagram from M′ = det(M)^(−1/2) M, sizes judged with M (the mesh's metrics are then M′)", 0, true},
           {"off-centres",
            "unit-aware insertion: a Voronoi vertex of poor angle or too large gets its site at the off-centre on the way from its "
            "shortest edge's midpoint, where that edge's end is at unit distance (at least δ/(2 sin θ_bound), resp. the size; "
            "fields that vary)",
            0, true}},
          [](const common::Domain& domain, const fields::MetricField& field, const ParameterValues& values,
             const common::Budget& budget, unsigned, const common::Progress& progress) {
            const LsParameters p = parameters(values, budget);
            if (p.off_centres && field.name == "constant")
              throw ParameterError("--off-centres: LS with the constant field runs Del_M, which inserts at circumcentres only");
            LsResult r = refine_ls(domain, field, p, progress);
            std::vector<std::string> lines = report(r, p, domain, field.name == "constant");
            return Run{std::move(r), std::move(lines)};
          },
          /*dual_of_diagram=*/true,
          /*seeded=*/false,
          /*run3=*/{}};
}

}  // namespace anisocert::refiners::ls
