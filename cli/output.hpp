#pragma once
// How every command writes: standard output all at once, files all or nothing (DESIGN.md:
// "nothing is written half-way"), progress lines on standard error, JSON rendering; and exact
// numbers given as options.
#include "io/reports/printed.hpp"
#include "numbers/rational.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace anisocert::cli {

using Json = nlohmann::ordered_json;

// Parses the text of option `name` exactly, within the magnitudes anisocert reads
// (parse_input_number), or throws UsageError naming the option and text.
Rational parse_option(const std::string& name, const std::string& text);

using io::as_printed;

// Writes all of `text` to standard output at once: nothing is printed half-way.
void emit(const std::string& text);
// The progress callback of long runs: "anisocert: LINE" on standard error, or nothing when quiet.
std::function<void(const std::string&)> progress_printer(bool quiet);
std::string render(const Json& j);
// Writes every file through a temporary file beside it, and renames them only once all were
// written: a command's outputs are all there, complete, or none is (DESIGN.md: nothing is written
// half-way; a failing rename, after every write succeeded, is the only way to leave some). Throws
// UsageError naming the path that cannot be written.
struct OutputFile {
  std::string path, content;
  // When set, writes the file instead of `content`: an output too large to hold twice (a report
  // listing every witness of a bad mesh) is streamed into the temporary file.
  std::function<void(std::ostream&)> write = {};
};
void write_files_atomically(const std::vector<OutputFile>& files);
// Before long work: refuses (UsageError) the outputs write_files_atomically would fail to write
// — two at one path, a directory, a folder that is missing or not writable — by creating and
// removing each one's temporary file. Empty paths (outputs not asked for) are skipped.
void check_outputs(const std::vector<std::string>& paths);
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace anisocert::cli
