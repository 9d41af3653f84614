#include "refiners/bwy/entry.hpp"

#include "refiners/bwy/bwy_refiner.hpp"
#include "refiners/common/summary.hpp"
#include "theory/bwy_section4.hpp"
#include "theory/ls_theorem9.hpp"

#include <cmath>
#include <sstream>

namespace anisocert::refiners::bwy {
namespace {

constexpr mpfr_prec_t precision = 128;

BwyParameters parameters(const ParameterValues& v, const common::Budget& budget) {
  BwyParameters p;
  static_cast<common::Budget&>(p) = budget;
  p.shape_bound = v.at("shape-bound"), p.distortion = v.at("distortion"), p.size = v.at("size");
  p.off_centres = v.at("off-centres") != 0;
  if (!(p.shape_bound > 1 && std::isfinite(p.shape_bound)))
    throw ParameterError("--shape-bound " + shortest_decimal(p.shape_bound) + " is out of range: need 1 < B < ∞ (BWY Lemma 2 takes B > 1)");
  if (!(p.distortion == 0 || (p.distortion >= 1 && std::isfinite(p.distortion))))
    throw ParameterError("--distortion " + shortest_decimal(p.distortion) + " is out of range: need G >= 1, or 0 for the largest G of Lemma 2");
  if (!(p.size >= 0 && std::isfinite(p.size)))
    throw ParameterError("--size " + shortest_decimal(p.size) + " is out of range: need 0 <= size < ∞ (0: no size rule)");
  // The largest G Lemma 2 admits with B, rounded down to a double (so that Lemma 2 holds at it).
  if (p.distortion == 0) p.distortion = theory::bwy_lemma2_gamma_max(Rational(p.shape_bound), precision).lower_double();
  return p;
}

std::string holds(bool b) { return b ? "holds" : "fails"; }

// BWY §4.2's conditions on B and G, decided exactly, and LS Corollary 10's angle when they allow.
std::string section42_line(const BwyParameters& p) {
  const Rational B(p.shape_bound), G(p.distortion);
  const theory::BwyConditions c = theory::bwy_s42_conditions(B, G);
  std::ostringstream o;
  o.precision(10);
  o << "  BWY §4.2 (decided exactly) for B = " << p.shape_bound << ", G = " << p.distortion << ": Lemma 2 " << holds(c.lemma2)
    << ", G²√(G⁴−1) ≤ 1 " << holds(c.violator_factor) << ", G²√(G²+1) ≤ B " << holds(c.shape_factor) << ": ";
  o << (c.positive_interdistance() ? "a positive minimal inter-distance where bdr_min(G) > 0 (sites with distortion below G)"
                                   : "no termination guarantee");
  if (c.angle_bound && theory::ls_t9_gamma_in_range(G) && theory::ls_t9_beta_in_range(B)) {
    const Interval a = theory::ls_c10_min_angle_deg(Interval(theory::ls_chi(B, G), precision), Interval(G, precision));
    o.precision(6);
    o << "; (G²−1)B² < 1: no angle below " << a.lower_double() << "° as measured by a point whose distortion to the triangle's "
      << "vertices is at most G (LS Corollary 10)";
  } else {
    o << "; (G²−1)B² < 1 " << holds(c.angle_bound) << ", no angle bound from LS Corollary 10";
  }
  return o.str();
}

std::vector<std::string> report(const BwyResult& r, const BwyParameters& p) {
  std::vector<std::string> lines{
      common::size_line(r, "BWY refiner"),
      common::stop_line(r, r.left_counted ? "encroached subsegments: " + std::to_string(r.encroached_left) +
                                                ", subsegments that are no edge: " + std::to_string(r.unedged_left) +
                                                ", Voronoi vertices a rule applies to: " + std::to_string(r.violators_left)
                                          : "what is left not counted (the time budget is spent)"),
      section42_line(p), common::rule_counts_line(r)};
  if (r.exempt_left > 0)
    lines.push_back("  left badly shaped at small input angles: " + std::to_string(r.exempt_left) +
                    " triangles across two segments that meet at less than 60° in the metric (their shortest edge joins the "
                    "two on one shell; rule 3 leaves them: docs/refiners.md § Concentric shells at sharp corners)");
  std::ostringstream o;
  o << "  parameters: B = " << p.shape_bound << ", G = " << p.distortion << ", size = " << p.size << (p.size > 0 ? "" : " (no size rule)")
    << (p.off_centres ? ", off-centres (rules 4 and 5 took another vertex they allow " + std::to_string(r.other_vertex_choices) + " times)" : "");
  lines.push_back(o.str());
  return lines;
}

}  // namespace

RefinerEntry entry() {
  const BwyParameters d;
  return {"bwy",
          "Boissonnat–Wormser–Yvinec's variant of LS refinement (BWY §3.2.2: encroached subsegments, subsegments that are no "
          "edge, then Voronoi vertices in Ω that are badly shaped (radius-edge ratio above B), share their triangle, or whose "
          "triangles overlap), on the true diagram; the mesh is T, the duals of the Voronoi vertices in Ω",
          {{"shape-bound", "shape bound B > 1: a Voronoi vertex with radius-edge ratio r(v)/δ(t_v) above B is badly shaped", d.shape_bound},
           {"distortion", "distortion coefficient G of BWY §4.2's conditions (reported, not used), 0: the largest G of Lemma 2 for B",
            d.distortion},
           {"size", "largest radius r(v) of a Voronoi vertex in the metric, 0 for none", d.size},
           {"off-centres",
            "unit-aware insertion: a badly shaped or too large Voronoi vertex gets its site at the off-centre on the way from its shortest "
            "edge's midpoint, where that edge's end is at unit distance (at least B δ, resp. the size; docs/refiners.md)",
            0, true}},
          [](const common::Domain& domain, const fields::MetricField& field, const ParameterValues& values,
             const common::Budget& budget, unsigned, const common::Progress& progress) {
            const BwyParameters p = parameters(values, budget);
            BwyResult r = refine_bwy(domain, field, p, progress);
            std::vector<std::string> lines = report(r, p);
            return Run{std::move(r), std::move(lines)};
          },
          /*dual_of_diagram=*/true,
          /*seeded=*/false,
          /*run3=*/{}};
}

}  // namespace anisocert::refiners::bwy
