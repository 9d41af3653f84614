#include "cli/output.hpp"

#include "cli/usage_error.hpp"
#include "numbers/decimal_enclosure.hpp"
#include "theory/precision.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace anisocert::cli {

mpfr_prec_t OutputOptions::precision() const { return theory::working_precision(digits); }

void add_output_options(CLI::App& command, OutputOptions& options) {
  options.digits = theory::default_digits;
  command.add_flag("--json", options.json, "Machine-readable JSON on standard output");
  command.add_option("--digits", options.digits, "Significant decimal digits of each interval endpoint")
      ->check(CLI::Range(10, 2000))
      ->capture_default_str();
}

Rational parse_option(const std::string& name, const std::string& text) {
  try {
    return parse_rational(text);
  } catch (const NumberSyntaxError& e) {
    throw UsageError(name + ": " + e.what());
  }
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

void emit(const std::string& text) {
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);
}

std::function<void(const std::string&)> progress_printer(bool quiet) {
  if (quiet) return {};
  return [](const std::string& line) { std::cerr << "anisocert: " << line << "\n"; };
}

std::string render(const Json& j) { return j.dump(2) + "\n"; }

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << content;
    out.flush();
    if (!out) {
      std::remove(temporary.c_str());
      throw UsageError("cannot write " + path);
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw UsageError("cannot write " + path);
  }
}

}  // namespace anisocert::cli
