// `anisocert theory lu`: the parameter conditions of LU Theorem 4.5 (locally uniform
// anisotropic meshing), decided exactly.

#include "cli/theory_output.hpp"
#include "cli/command.hpp"
#include "cli/usage_error.hpp"
#include "theory/lu_theorem45.hpp"

#include <sstream>

namespace anisocert::cli {
namespace {

struct LuOptions {
  std::string rho0, gamma0, delta, beta;
  OutputOptions output;
};

int run_lu(const LuOptions& o) {
  theory::LuParameters p{parse_option("--rho0", o.rho0), parse_option("--gamma0", o.gamma0),
                         parse_option("--delta", o.delta), parse_option("--beta", o.beta)};
  theory::LuConditions c;
  try {
    c = theory::lu_t45_conditions(p);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const ConditionReport r = report_conditions({
      {"rho0_above_2", "ρ₀ > 2", c.rho0_above_2},
      {"delta_rho0", "(1−δ)³ρ₀ > 2", c.delta_rho0},
      {"delta_beta", "(1−δ)³β > 2", c.delta_beta},
      {"lemma43", "Lemma 4.3: (1−δ)³ρ₀ > 2γ₀³", c.lemma43},
      {"lemma44", "Lemma 4.4: (1−δ)³β > 2γ₀³", c.lemma44},
  });
  const std::vector<std::string> not_checked = {
      "K(rho0, beta) max(f(gamma0), g(gamma0), h(gamma0)) beta^2 < (4/3) pi delta^2: the paper gives no closed "
      "form for K, f, g, h",
      "the angle at each boundary edge, for the metric of any point of it, is > 90 degrees: a property of the "
      "domain and the metric field"};
  std::ostringstream text;
  text << "LU Theorem 4.5 (locally uniform anisotropic meshing) for ρ₀ = " << to_exact_string(p.rho0)
       << ", γ₀ = " << to_exact_string(p.gamma0) << ", δ = " << to_exact_string(p.delta)
       << ", β = " << to_exact_string(p.beta) << " (decided exactly):\n"
       << r.text;
  for (const std::string& n : not_checked) text << "  not checked: " << n << "\n";
  text << "  verdict: " << (c.all() ? "all decidable conditions hold" : "some condition fails") << "\n";
  Json j{{"rho0", to_exact_string(p.rho0)},
         {"gamma0", to_exact_string(p.gamma0)},
         {"delta", to_exact_string(p.delta)},
         {"beta", to_exact_string(p.beta)},
         {"LU_T45_conditions", r.conditions},
         {"holds", c.all()},
         {"failing", r.failing},
         {"not_checked", not_checked}};
  emit(o.output.json ? render(j) : text.str());
  return c.all() ? 0 : 1;
}

}  // namespace

void add_theory_lu(CLI::App& theory, int& exit_code) {
  auto o = std::make_shared<LuOptions>();
  CLI::App* lu = theory.add_subcommand(
      "lu",
      "LU Theorem 4.5: which of ρ₀ > 2, (1−δ)³ρ₀ > 2, (1−δ)³β > 2, (1−δ)³ρ₀ > 2γ₀³, (1−δ)³β > 2γ₀³ hold, exactly.\n"
      "Exit 1 when one fails.");
  lu->add_option("--rho0", o->rho0, "Radius-edge ratio bound ρ₀ > 0")->required();
  lu->add_option("--gamma0", o->gamma0, "Distortion bound γ₀ > 1")->required();
  lu->add_option("--delta", o->delta, "Picking ratio δ > 0")->required();
  lu->add_option("--beta", o->beta, "Size ratio β > 0")->required();
  add_output_options(*lu, o->output);
  lu->callback([o, &exit_code] { exit_code = run_lu(*o); });
}

}  // namespace anisocert::cli
