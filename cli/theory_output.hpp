#pragma once
// What the theory commands (`theory`, `theory chi|bwy|lu`, `conics`) share: --json / --digits,
// certified enclosures as JSON {"lo": "...", "hi": "..."} or as their certified digits, and the
// report of a theorem's decided conditions.
#include "cli/output.hpp"
#include "numbers/interval.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace anisocert::cli {

struct OutputOptions {
  bool json = false;
  int digits = 40;
  mpfr_prec_t precision() const;
};

void add_output_options(CLI::App& command, OutputOptions& options);

// {"lo": "...", "hi": "..."}: decimal strings rounded outward to `digits` significant digits.
Json enclosure_json(const anisocert::Interval& x, int digits);
Json enclosure_json(const std::optional<anisocert::Interval>& x, int digits);  // null when absent

// The certified leading digits of x for tables: at most `width` characters after which a
// trailing … marks truncation, but never cut inside the integer part.
std::string enclosure_text(const anisocert::Interval& x, int digits, std::size_t width = 24);

// One decided condition of a theorem: its JSON key, its statement, and whether it holds.
struct Condition {
  std::string key;
  std::string statement;
  bool holds;
};
// {"key": holds, ...} and the array of failing keys, plus one text line per condition.
struct ConditionReport {
  Json conditions = Json::object();
  Json failing = Json::array();
  std::string text;
};
ConditionReport report_conditions(const std::vector<Condition>& conditions);

}  // namespace anisocert::cli
