#include "cli/output.hpp"

#include "cli/usage_error.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace anisocert::cli {

Rational parse_option(const std::string& name, const std::string& text) {
  try {
    return parse_rational(text);
  } catch (const NumberSyntaxError& e) {
    throw UsageError(name + ": " + e.what());
  }
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
