#pragma once
// Runs the anisocert program as a user does (ANISOCERT_BIN, set by CMake), or any command line,
// and collects its exit code, standard output and standard error.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

struct Outcome {
  int exit_code;
  std::string out, err;
};

// A shell command line, its standard error collected apart.
inline Outcome run_command(const std::string& command_line) {
  // One file per process: CTest runs the tests of this file in parallel processes.
  const std::string err_file = ::testing::TempDir() + "anisocert_stderr_" + std::to_string(getpid()) + ".txt";
  const std::string command = command_line + " 2>" + err_file;
  FILE* pipe = popen(command.c_str(), "r");
  Outcome r{-1, "", ""};
  std::array<char, 4096> buf{};
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), pipe)) > 0;) r.out.append(buf.data(), n);
  int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err_file);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  std::remove(err_file.c_str());
  return r;
}

inline Outcome run(const std::string& args) { return run_command(std::string(ANISOCERT_BIN) + " " + args); }

// An empty folder of its own under the test temporary directory: PREFIX_NAME_PID.
inline std::filesystem::path fresh_folder(const std::string& prefix, const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(::testing::TempDir()) / (prefix + "_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace
