// `anisocert theory bwy`: Boissonnat–Wormser–Yvinec §4 (Lemma 2, §4.2) for a shape bound B
// and, optionally, a distortion coefficient G.

#include "cli/theory_output.hpp"
#include "cli/command.hpp"
#include "cli/usage_error.hpp"
#include "numbers/excerpt.hpp"
#include "theory/bwy_section4.hpp"
#include "numbers/decimal_enclosure.hpp"
#include "theory/ls_theorem9.hpp"

#include <sstream>
#include <stdexcept>

namespace anisocert::cli {
namespace {


struct BwyOptions {
  std::string B, G;
  OutputOptions output;
};

int run_bwy(const BwyOptions& o) {
  const OutputOptions& out = o.output;
  const Rational B = parse_option("--B", o.B);
  if (!(B > 1)) throw UsageError("--B " + excerpt(o.B) + ": BWY Lemma 2 needs a shape bound B > 1");
  const Interval gamma_max = theory::bwy_lemma2_gamma_max(B, out.precision());
  const anisocert::DecimalEnclosure printed = anisocert::to_decimal(gamma_max, out.digits);
  if (!theory::bwy_lemma2_gamma_max_bracket_verified(B, parse_rational(printed.lo), parse_rational(printed.hi)))
    throw std::logic_error("printed enclosure of BWY γ_max(" + to_exact_string(B) + ") fails its exact check");
  Json j{{"B", to_exact_string(B)}, {"BWY_L2_gamma_max", enclosure_json(gamma_max, out.digits)}};
  std::ostringstream text;
  text << "BWY §4 (Boissonnat, Wormser & Yvinec, LS revisited) for B = " << to_exact_string(B) << "\n"
       << "  Lemma 2: (γ²−1)(1+γ)²(1+4γ)²B⁴ <= 1 exactly for 1 <= γ <= γ_max = " << enclosure_text(gamma_max, out.digits)
       << "\n";
  int exit_code = 0;
  if (!o.G.empty()) {
    const Rational G = parse_option("--G", o.G);
    if (!(G >= 1)) throw UsageError("--G " + excerpt(o.G) + ": the distortion coefficient G must be >= 1");
    const theory::BwyConditions c = theory::bwy_s42_conditions(B, G);
    const theory::BwyInterdistanceFactors f = theory::bwy_s42_factors(B, G, out.precision());
    const ConditionReport r = report_conditions({
        {"lemma2", "Lemma 2: (G²−1)(1+G)²(1+4G)²B⁴ <= 1", c.lemma2},
        {"violator_factor", "§4.2: G²√(G⁴−1) <= 1", c.violator_factor},
        {"shape_factor", "§4.2: G²√(G²+1) <= B", c.shape_factor},
        {"angle_bound", "§4.2: (G²−1)B² < 1", c.angle_bound},
    });
    text << "  G = " << to_exact_string(G) << " (decided exactly):\n" << r.text;
    j["G"] = to_exact_string(G);
    j["BWY_S42_conditions"] = r.conditions;
    j["positive_interdistance"] = c.positive_interdistance();
    j["holds"] = c.all();
    j["failing"] = r.failing;
    j["BWY_S42_factors"] = Json{{"violator", enclosure_json(f.violator, out.digits)},
                                {"shape", enclosure_json(f.shape, out.digits)},
                                {"bdr", enclosure_json(f.bdr, out.digits)},
                                {"lfs", enclosure_json(f.lfs, out.digits)}};
    text << "  d^w_min >= min(" << (f.violator ? enclosure_text(*f.violator, out.digits, 14) : std::string("∞"))
         << "·d_min, " << enclosure_text(f.shape, out.digits, 14) << "·d_min, "
         << enclosure_text(f.bdr, out.digits, 14) << "·bdr_min(G), " << enclosure_text(f.lfs, out.digits, 14)
         << "·lfs_min)\n";
    // (G²−1)B² < 1 is χ(B, G) > 0 of LS Theorem 9; with its ranges, Corollary 10 gives the angle.
    Json angle = nullptr;
    const Rational chi = theory::ls_chi(B, G);
    if (c.angle_bound && theory::ls_t9_gamma_in_range(G) && theory::ls_t9_beta_in_range(B)) {
      const Interval a = theory::ls_c10_min_angle_deg(Interval(chi, out.precision()), Interval(G, out.precision()));
      angle = enclosure_json(a, out.digits);
      text << "  LS Corollary 10 with β = B, γ = G: no angle below " << enclosure_text(a, out.digits)
           << "° measured by any point of a triangle\n";
    }
    j["LS_C10_min_angle_deg"] = angle;
    text << "  verdict: " << (c.all() ? "all conditions hold" : "some condition fails") << "\n";
    exit_code = c.all() ? 0 : 1;
  }
  emit(out.json ? render(j) : text.str());
  return exit_code;
}

}  // namespace

void add_theory_bwy(CLI::App& theory, int& exit_code) {
  auto o = std::make_shared<BwyOptions>();
  CLI::App* bwy = theory.add_subcommand(
      "bwy",
      "BWY §4: the largest γ admitted by Lemma 2 for a shape bound B > 1 (certified), and with --G the exact\n"
      "decision of the §4.2 conditions and the inter-distance factors. Exit 1 when a condition fails.");
  bwy->add_option("--B", o->B, "Shape (radius-edge) bound B > 1, exact decimal or fraction")->required();
  bwy->add_option("--G", o->G, "Distortion coefficient G >= 1, exact decimal or fraction");
  add_output_options(*bwy, o->output);
  bwy->callback([o, &exit_code] { exit_code = run_bwy(*o); });
}

}  // namespace anisocert::cli
