#pragma once
// What every subcommand shares: --json / --digits, exact-number options, and the JSON shape
// of a certified enclosure {"lo": "...", "hi": "..."}.

#include "numbers/rational.hpp"
#include "numbers/interval.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace anisocert::cli {

using Json = nlohmann::ordered_json;

struct OutputOptions {
  bool json = false;
  int digits = 40;
  mpfr_prec_t precision() const;
};

void add_output_options(CLI::App& command, OutputOptions& options);

// Parses the text of option `name` exactly, or throws UsageError naming the option and text.
Rational parse_option(const std::string& name, const std::string& text);

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

// Writes all of `text` to standard output at once: nothing is printed half-way.
void emit(const std::string& text);
// The progress callback of long runs: "anisocert: LINE" on standard error, or nothing when quiet.
std::function<void(const std::string&)> progress_printer(bool quiet);
std::string render(const Json& j);
// Writes `content` to `path` through a temporary file in the same directory and a rename, so
// that the file is either absent, or complete (DESIGN.md: nothing is written half-way).
// Throws UsageError naming the path when it cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace anisocert::cli
