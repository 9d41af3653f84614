// `anisocert theory`: LS Theorem 11 (γ(θ), segment angle, distance factor, θ_max) and the LS
// Lemma factors at γ(θ), for θ_bound in degrees.

#include "cli/command.hpp"

#include "cli/theory_output.hpp"
#include "cli/usage_error.hpp"
#include "numbers/excerpt.hpp"
#include "numbers/decimal_enclosure.hpp"
#include "theory/ls_lemma_factors.hpp"
#include "theory/ls_theorem11.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

namespace anisocert::cli {
namespace {


struct TheoryOptions {
  std::vector<std::string> thetas;
  OutputOptions output;
};

const std::vector<std::string> default_thetas = {"0", "5", "10", "15", "20"};

Rational admissible_theta(const std::string& text, const Interval& theta_max, int digits) {
  Rational theta = parse_option("--theta", text);
  if (!theory::ls_t11_theta_admissible(theta))
    throw UsageError("--theta " + excerpt(text) + ": out of range: LS Theorem 11 needs 0 <= θ_bound < arcsin(1/(2√2)) = " +
                     enclosure_text(theta_max, digits, 16) + " degrees");
  return theta;
}

// Rejects an enclosure whose printed decimals do not bracket the root (never expected: the
// decimals are rounded outward from a certified bracket; this re-checks what is printed).
void verify_printed_gamma(const Rational& theta, const Interval& gamma, int digits) {
  anisocert::DecimalEnclosure d = anisocert::to_decimal(gamma, digits);
  // At γ's own precision, which ls_t11_gamma raises near θ_max.
  if (!theory::ls_t11_gamma_bracket_verified(theta, parse_rational(d.lo), parse_rational(d.hi), gamma.precision()))
    throw std::logic_error("printed enclosure of γ(" + to_exact_string(theta) + ") does not bracket the root");
}

Json theorem11_json(const Rational& theta, const Interval& theta_max, const OutputOptions& out) {
  const mpfr_prec_t prec = out.precision();
  const int n = out.digits;
  Interval gamma = theory::ls_t11_gamma(theta, prec);
  verify_printed_gamma(theta, gamma, n);
  return Json{
      {"theta_deg", to_exact_string(theta)},
      {"gamma", enclosure_json(gamma, n)},
      {"segment_angle_deg", enclosure_json(theory::ls_t11_segment_angle_deg(gamma), n)},
      {"distance_factor", enclosure_json(theory::ls_t11_distance_factor(gamma), n)},
      {"theta_max_deg", enclosure_json(theta_max, n)},
      {"LS_L5_factor", enclosure_json(theory::ls_lemma5_factor(gamma), n)},
      {"LS_L14_factor", enclosure_json(theory::ls_lemma14_factor(gamma), n)},
      {"LS_L18_factor", enclosure_json(theory::ls_lemma18_factor(gamma), n)},
      {"LS_L21_site_factor", enclosure_json(theory::ls_lemma21_site_factor(gamma), n)},
      {"LS_L21_bdr_factor", enclosure_json(theory::ls_lemma21_bdr_factor(gamma), n)},
      {"LS_L23_factor", enclosure_json(theory::ls_lemma23_factor(gamma), n)},
  };
}

std::string pad(const std::string& s, std::size_t width) {
  // Display width: count UTF-8 code points.
  std::size_t points = 0;
  for (unsigned char c : s) points += (c & 0xC0) != 0x80;
  return s + std::string(points < width ? width - points : 1, ' ');
}

std::string theorem11_table(const std::vector<Rational>& thetas, const Interval& theta_max, const OutputOptions& out) {
  std::ostringstream os;
  os << "LS Theorem 11 (Labelle & Shewchuk 2003, §10): certified enclosures.\n"
     << "Every digit shown is correct (a truncation of every point of the enclosing interval);\n"
     << "--json gives the enclosures [lo, hi] to " << out.digits << " significant digits.\n\n";
  os << pad("θ_bound (°)", 13) << pad("γ: root > 1 of γ⁸+2γ⁴√(γ²+1)sinθ−γ⁴−1", 43)
     << pad("segment angle 2·arcsin(γ²/2) (°)", 36) << "distance factor 1/((γ⁵+γ³)√(γ²+1))\n";
  for (const Rational& theta : thetas) {
    Interval gamma = theory::ls_t11_gamma(theta, out.precision());
    verify_printed_gamma(theta, gamma, out.digits);
    os << pad(to_exact_string(theta), 13) << pad(enclosure_text(gamma, out.digits), 43)
       << pad(enclosure_text(theory::ls_t11_segment_angle_deg(gamma), out.digits), 36)
       << enclosure_text(theory::ls_t11_distance_factor(gamma), out.digits) << "\n";
  }
  os << "\nθ_bound must be below arcsin(1/(2√2)) = " << enclosure_text(theta_max, out.digits) << " degrees.\n"
     << "More: anisocert theory chi|bwy|lu --help (LS Theorem 9/Corollary 10, BWY §4, LU Theorem 4.5).\n";
  return os.str();
}

}  // namespace

void add_theory(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<TheoryOptions>();
  CLI::App* theory = app.add_subcommand(
      "theory",
      "Certified constants of the papers. Without a subcommand: LS Theorem 11 (γ(θ_bound), the angle between\n"
      "adjoining segments, the minimal-distance factor, θ_bound's upper limit) and the LS Lemma factors at γ.");
  CLI::Option* theta = theory->add_option(
      "--theta", options->thetas, "θ_bound in degrees, an exact decimal or fraction (repeatable); default 0 5 10 15 20");
  add_output_options(*theory, options->output);
  theory->callback([theory, options, &exit_code] {
    if (!theory->get_subcommands().empty()) return;  // a subcommand ran
    const OutputOptions& out = options->output;
    Interval theta_max = theory::ls_t11_theta_max_deg(out.precision());
    const std::vector<std::string>& texts = options->thetas.empty() ? default_thetas : options->thetas;
    std::vector<Rational> thetas;
    for (const std::string& t : texts) thetas.push_back(admissible_theta(t, theta_max, out.digits));
    if (out.json) {
      Json rows = Json::array();
      for (const Rational& theta : thetas) rows.push_back(theorem11_json(theta, theta_max, out));
      emit(render(rows.size() == 1 ? rows[0] : rows));
    } else {
      emit(theorem11_table(thetas, theta_max, out));
    }
    exit_code = 0;
  });
  for (const Command& c : theory_commands()) c.add(*theory, exit_code);
  for (CLI::App* sub : theory->get_subcommands(std::function<bool(CLI::App*)>{})) sub->excludes(theta);  // table only
}

}  // namespace anisocert::cli
