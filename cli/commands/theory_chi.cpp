// `anisocert theory chi`: LS Theorem 9 and Corollary 10 for given β and γ.

#include "cli/theory_output.hpp"
#include "cli/command.hpp"
#include "cli/usage_error.hpp"
#include "numbers/excerpt.hpp"
#include "theory/ls_theorem9.hpp"

#include <sstream>

namespace anisocert::cli {
namespace {


struct ChiOptions {
  std::string beta, gamma;
  OutputOptions output;
};

int run_chi(const ChiOptions& o) {
  const Rational beta = parse_option("--beta", o.beta);
  const Rational gamma = parse_option("--gamma", o.gamma);
  if (!(beta > 0)) throw UsageError("--beta " + excerpt(o.beta) + ": β must be > 0 (χ = 1/(2β) − (γ²−1)β/2)");
  if (!(gamma > 0)) throw UsageError("--gamma " + excerpt(o.gamma) + ": γ must be > 0");
  const OutputOptions& out = o.output;
  const Rational chi = theory::ls_chi(beta, gamma);
  const bool gamma_ok = theory::ls_t9_gamma_in_range(gamma);
  const bool beta_ok = theory::ls_t9_beta_in_range(beta);
  const bool applies = gamma_ok && beta_ok && chi > 0;
  Json bounds = nullptr;
  std::ostringstream text;
  text << "LS Theorem 9 / Corollary 10 (Labelle & Shewchuk 2003, §6) for β = " << to_exact_string(beta)
       << ", γ = " << to_exact_string(gamma) << "\n"
       << "  range 1 <= γ <= √2:     " << (gamma_ok ? "holds" : "FAILS") << "\n"
       << "  range β >= 1/√2:        " << (beta_ok ? "holds" : "FAILS") << "\n"
       << "  χ = 1/(2β) − (γ²−1)β/2 = " << to_exact_string(chi) << (chi > 0 ? " > 0" : " <= 0") << "\n";
  Json j{{"beta", to_exact_string(beta)},
         {"gamma", to_exact_string(gamma)},
         {"LS_T9_gamma_in_range", gamma_ok},
         {"LS_T9_beta_in_range", beta_ok},
         {"chi", to_exact_string(chi)},
         {"chi_positive", chi > 0},
         {"applies", applies}};
  if (applies) {
    const Interval chi_i(chi, out.precision()), gamma_i(gamma, out.precision());
    const Interval t9 = theory::ls_t9_min_angle_deg(chi_i);
    const Interval c10_min = theory::ls_c10_min_angle_deg(chi_i, gamma_i);
    const Interval c10_max = theory::ls_c10_max_angle_deg(chi_i, gamma_i);
    j["LS_T9_min_angle_deg"] = enclosure_json(t9, out.digits);
    j["LS_C10_min_angle_deg"] = enclosure_json(c10_min, out.digits);
    j["LS_C10_max_angle_deg"] = enclosure_json(c10_max, out.digits);
    text << "  Theorem 9: a Voronoi vertex with r/ℓ <= β and τ <= γ is wedged; every angle >= arcsin χ = "
         << enclosure_text(t9, out.digits) << "° (from some vertex)\n"
         << "  Corollary 10: measured by any p with τ(p, vᵢ) <= γ, every angle lies in ["
         << enclosure_text(c10_min, out.digits) << "°, " << enclosure_text(c10_max, out.digits) << "°]\n";
  } else {
    text << "  The theorem's hypotheses on (β, γ) do not hold: it gives no bound.\n";
  }
  emit(out.json ? render(j) : text.str());
  return applies ? 0 : 1;
}

}  // namespace

void add_theory_chi(CLI::App& theory, int& exit_code) {
  auto o = std::make_shared<ChiOptions>();
  CLI::App* chi = theory.add_subcommand(
      "chi",
      "LS Theorem 9 and Corollary 10: χ(β, γ) exactly, the ranges 1 <= γ <= √2, β >= 1/√2, and the certified\n"
      "angle bounds arcsin χ, arcsin(χ/γ²), 2·arccos(χ/γ²) in degrees. Exit 0 when the theorem applies\n"
      "(ranges hold and χ > 0), 1 when it does not.");
  chi->add_option("--beta", o->beta, "Radius-edge bound β (exact decimal or fraction)")->required();
  chi->add_option("--gamma", o->gamma, "Distortion bound γ (exact decimal or fraction)")->required();
  add_output_options(*chi, o->output);
  chi->callback([o, &exit_code] { exit_code = run_chi(*o); });
}

}  // namespace anisocert::cli
