#pragma once
// How every command writes: standard output all at once, files all or nothing (DESIGN.md:
// "nothing is written half-way"), progress lines on standard error, JSON rendering; and exact
// numbers given as options.
#include "numbers/rational.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace anisocert::cli {

using Json = nlohmann::ordered_json;

// Parses the text of option `name` exactly, or throws UsageError naming the option and text.
Rational parse_option(const std::string& name, const std::string& text);

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
