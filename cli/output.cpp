#include "cli/output.hpp"

#include "cli/usage_error.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace anisocert::cli {

Rational parse_option(const std::string& name, const std::string& text) {
  try {
    return parse_input_number(text);
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

namespace {

// Why a file cannot be written, when the system said ("No such file or directory").
std::string reason(int error) { return error != 0 ? std::string(": ") + std::strerror(error) : std::string(); }

std::string partial(const std::string& path) { return path + ".partial"; }

// What would make a rename fail after others succeeded: two outputs at one path, or a path that
// is a directory.
void check_paths(const std::vector<std::string>& paths) {
  for (std::size_t i = 0; i < paths.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      if (paths[i] == paths[j]) throw UsageError("cannot write " + paths[i] + ": two outputs given the same path");
    if (std::filesystem::is_directory(paths[i])) throw UsageError("cannot write " + paths[i] + ": it is a directory");
  }
}

}  // namespace

void check_outputs(const std::vector<std::string>& paths) {
  std::vector<std::string> given;
  for (const std::string& p : paths)
    if (!p.empty()) given.push_back(p);
  check_paths(given);
  for (const std::string& p : given) {
    errno = 0;
    const bool writable = std::ofstream(partial(p), std::ios::binary | std::ios::trunc).good();
    const int error = errno;
    std::remove(partial(p).c_str());
    if (!writable) throw UsageError("cannot write " + p + reason(error));
  }
}

void write_files_atomically(const std::vector<OutputFile>& files) {
  std::vector<std::string> paths;
  for (const OutputFile& f : files) paths.push_back(f.path);
  check_paths(paths);  // before anything is written
  const auto remove_partials = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) std::remove(partial(files[i].path).c_str());
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    errno = 0;
    std::ofstream out(partial(files[i].path), std::ios::binary | std::ios::trunc);
    if (out) {
      try {
        if (files[i].write) files[i].write(out);
        else out << files[i].content;
      } catch (...) {
        out.close();
        remove_partials(0, i + 1);
        throw;
      }
      out.close();  // flushes: a full disk fails here at the latest
    }
    if (!out) {
      const int error = errno;
      remove_partials(0, i + 1);
      throw UsageError("cannot write " + files[i].path + reason(error));
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i)
    if (std::rename(partial(files[i].path).c_str(), files[i].path.c_str()) != 0) {
      const int error = errno;
      remove_partials(i, files.size());
      throw UsageError("cannot write " + files[i].path + reason(error));
    }
}

void write_file_atomically(const std::string& path, const std::string& content) { write_files_atomically({{path, content}}); }

}  // namespace anisocert::cli
