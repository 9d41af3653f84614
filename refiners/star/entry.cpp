#include "refiners/star/entry.hpp"

#include "refiners/common/summary.hpp"
#include "refiners/star/star_refiner.hpp"
#include "refiners/star/star_refiner3.hpp"
#include "theory/lu_theorem45.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace anisocert::refiners::star {
namespace {

RefineParameters parameters(const ParameterValues& v, const common::Budget& budget, unsigned seed) {
  RefineParameters p;
  static_cast<common::Budget&>(p) = budget;
  p.rho0 = v.at("rho0"), p.gamma0 = v.at("gamma0"), p.delta = v.at("delta"), p.beta = v.at("beta"), p.size = v.at("size");
  p.seed = seed;
  const auto require = [&](bool holds, const char* name, const char* range) {
    if (!holds) {
      std::ostringstream o;
      o << "--" << name << " " << v.at(name) << " is out of range: need " << range;
      throw ParameterError(o.str());
    }
  };
  require(p.rho0 > 0 && std::isfinite(p.rho0), "rho0", "0 < ρ₀ < ∞");
  require(p.gamma0 > 1 && std::isfinite(p.gamma0), "gamma0", "1 < γ₀ < ∞");
  require(p.delta > 0 && p.delta < 1, "delta", "0 < δ < 1");
  require(p.beta > 0 && std::isfinite(p.beta), "beta", "0 < β < ∞");
  require(p.size > 0 && std::isfinite(p.size), "size", "0 < size < ∞");
  const double attempts = v.at("pick-attempts");
  if (!(attempts >= 0 && attempts <= 1000) || attempts != static_cast<int>(attempts))
    throw ParameterError("--pick-attempts must be an integer from 0 to 1000");
  p.pick_attempts = static_cast<int>(attempts);
  return p;
}

const char* yes(bool b) { return b ? "yes" : "no"; }

std::string pick_line(std::size_t rejected, std::size_t exhausted, std::size_t refinements, const RefineParameters& p, const char* kind) {
  std::ostringstream o;
  o << "  Pick_valid: " << rejected << " picked points discarded as γ₀-" << kind << ", " << exhausted << " of " << refinements
    << " refinements kept a forbidden point after " << p.pick_attempts << " discards";
  if (p.pick_attempts > 0 && 2 * exhausted > refinements)
    o << " (most: at this γ₀ the forbidden set covers most of each picking region; LU Lemma 3.15 needs γ₀ close to 1)";
  return o.str();
}

std::string parameters_line(const RefineParameters& p) {
  std::ostringstream o;
  o << "  parameters: ρ₀ = " << p.rho0 << ", γ₀ = " << p.gamma0 << ", δ = " << p.delta << ", β = " << p.beta << ", size = " << p.size;
  return o.str();
}

// LU Theorem 4.5's conditions on the parameters, decided exactly by theory/.
std::string theorem45_line(const RefineParameters& p) {
  const theory::LuConditions c = theory::lu_t45_conditions(
      {rational_from_double(p.rho0), rational_from_double(p.gamma0), rational_from_double(p.delta), rational_from_double(p.beta)});
  return std::string("  LU Theorem 4.5 conditions (decided exactly): ρ₀ > 2 ") + yes(c.rho0_above_2) + ", (1−δ)³ρ₀ > 2 " +
         yes(c.delta_rho0) + ", (1−δ)³β > 2 " + yes(c.delta_beta) + ", (1−δ)³ρ₀ > 2γ₀³ " + yes(c.lemma43) + ", (1−δ)³β > 2γ₀³ " +
         yes(c.lemma44);
}

// LU Lemma 4.1's hypothesis at Ω's ridges (StarResult3::right_or_acute_ridges).
std::string lemma41_line(const StarResult3& r) {
  std::string line = "  LU Lemma 4.1's hypothesis (dihedral angles > 90° in the metric, for rule 1 to end): ";
  if (r.right_or_acute_ridges.empty()) return line + "holds at every one of Ω's " + std::to_string(r.ridges) + " ridges";
  const auto& e = r.right_or_acute_ridges.front();
  return line + "not at " + std::to_string(r.right_or_acute_ridges.size()) + " of " + std::to_string(r.ridges) +
         " ridges (the first between vertices " + std::to_string(e[0]) + " and " + std::to_string(e[1]) +
         "; rule 1 may not end there: the run's end and its certificate say)";
}

std::vector<std::string> report3(const StarResult3& r, const RefineParameters& p) {
  return {
      common::size_line(r, "star refiner (3D)"),
      common::stop_line(r, "inconsistent star tetrahedra: " + std::to_string(r.inconsistent_tetrahedra) +
                               (r.empty_stars ? ", empty stars: " + std::to_string(r.empty_stars) : "")),
      "  boundary: " + std::to_string(r.subfacets) + " subfacets after " + std::to_string(r.boundary_splits) +
          " edge splits at exact midpoints (" + std::to_string(r.boundary_splits - r.snap_splits) +
          " for rule 1, " + std::to_string(r.snap_splits) + " by Insert_or_snap); the mesh's " + std::to_string(r.mesh.triangles.size()) +
          " boundary faces, " + std::to_string(r.faces_off_boundary) + " of them off ∂Ω",
      lemma41_line(r),
      pick_line(r.picks_rejected, r.picks_exhausted, r.refinements, p, "cospherical"), common::rule_counts_line(r), parameters_line(p),
      theorem45_line(p)};
}

std::vector<std::string> report(const StarResult& r, const RefineParameters& p) {
  std::vector<std::string> lines{common::size_line(r, "star refiner"),
                                 common::stop_line(r, "inconsistent star triangles: " + std::to_string(r.inconsistent_triangles) +
                                                          (r.empty_stars ? ", empty stars: " + std::to_string(r.empty_stars) : ""))};
  std::ostringstream o;
  o << "  LU Lemma 4.1 (boundary angles > 90° in the metric): ";
  if (r.acute_corners.empty()) {
    o << "holds at every corner";
  } else {
    o << "fails at corner(s)";
    for (int k : r.acute_corners) o << " " << k;
    o << " (encroachment there may not end)";
  }
  lines.push_back(o.str());
  lines.push_back(pick_line(r.picks_rejected, r.picks_exhausted, r.refinements, p, "cocircular"));
  lines.push_back(common::rule_counts_line(r));
  lines.push_back(parameters_line(p));
  lines.push_back(theorem45_line(p));
  return lines;
}

}  // namespace

RefinerEntry entry() {
  const RefineParameters d;
  return {"star",
          "locally uniform star sets (Boissonnat, Wormser & Yvinec; LU §4.1 rules (1) encroachment, (2) distortion, "
          "(3) radius-edge ratio, (4) size, (5) inconsistency)",
          {{"rho0", "radius-edge ratio bound ρ₀", d.rho0},
           {"gamma0", "distortion bound γ₀", d.gamma0},
           {"delta", "picking-region ratio δ", d.delta},
           {"beta", "cosphericity radius ratio β (checked against Theorem 4.5)", d.beta},
           {"size", "largest circumradius in the metric", d.size},
           {"pick-attempts", "Pick_valid: picked points that may be discarded as γ₀-cocircular before one is kept (0: no test)",
            static_cast<double>(d.pick_attempts)}},
          [](const common::Domain& domain, const fields::MetricField& field, const ParameterValues& values,
             const common::Budget& budget, unsigned seed, const common::Progress& progress) {
            const RefineParameters p = parameters(values, budget, seed);
            if (!domain.interior_segments().empty())
              throw common::DomainError("--algo star keeps no interior segments (LU §4.1 protects ∂Ω only): the domain's " +
                                        std::to_string(domain.interior_segments().size()) + " interior segments are for the other refiners");
            StarResult r = refine_star(domain, field, p, progress);
            std::vector<std::string> lines = report(r, p);
            return Run{std::move(r), std::move(lines)};
          },
          /*dual_of_diagram=*/false,
          /*seeded=*/true,
          [](const common::Domain3& domain, const fields::MetricField3& field, const ParameterValues& values,
             const common::Budget& budget, unsigned seed, const common::Progress& progress) {
            const RefineParameters p = parameters(values, budget, seed);
            StarResult3 r = refine_star3(domain, field, p, progress);
            std::vector<std::string> lines = report3(r, p);
            return Run3{std::move(r), std::move(lines)};
          }};
}

}  // namespace anisocert::refiners::star
