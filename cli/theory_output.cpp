#include "cli/theory_output.hpp"

#include "numbers/decimal_enclosure.hpp"
#include "theory/precision.hpp"

#include <algorithm>

namespace anisocert::cli {

mpfr_prec_t OutputOptions::precision() const { return theory::working_precision(digits); }

void add_output_options(CLI::App& command, OutputOptions& options) {
  options.digits = theory::default_digits;
  command.add_flag("--json", options.json, "Machine-readable JSON on standard output");
  command.add_option("--digits", options.digits, "Significant decimal digits of each interval endpoint")
      ->check(CLI::Range(10, 2000))
      ->capture_default_str();
}

Json enclosure_json(const anisocert::Interval& x, int digits) {
  anisocert::DecimalEnclosure d = anisocert::to_decimal(x, digits);
  return Json{{"lo", d.lo}, {"hi", d.hi}};
}

Json enclosure_json(const std::optional<anisocert::Interval>& x, int digits) {
  return x ? enclosure_json(*x, digits) : Json(nullptr);
}

std::string enclosure_text(const anisocert::Interval& x, int digits, std::size_t width) {
  std::string s = anisocert::certified_digits(anisocert::to_decimal(x, digits));
  const bool truncated = s.ends_with("…");
  if (truncated) s.erase(s.size() - std::string("…").size());
  // Shorten to `width` characters (all ASCII now), never into the integer part.
  const std::size_t dot = s.find('.');
  const std::size_t keep = std::max(width - 1, dot == std::string::npos ? s.size() : dot);
  if (s.size() > keep) return s.substr(0, keep) + "…";
  return truncated ? s + "…" : s;
}

ConditionReport report_conditions(const std::vector<Condition>& conditions) {
  ConditionReport r;
  for (const Condition& c : conditions) {
    r.conditions[c.key] = c.holds;
    if (!c.holds) r.failing.push_back(c.key);
    r.text += "    " + c.statement + ": " + (c.holds ? "holds" : "FAILS") + "\n";
  }
  return r;
}

}  // namespace anisocert::cli
