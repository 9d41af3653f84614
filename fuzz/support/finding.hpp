#pragma once
// A harness's verdict on one input (docs/fuzzing.md): an input that breaks a property is a finding.
// The harness prints what broke, on one line, and aborts, so that libFuzzer and AFL++ save the
// input as a crash, and the replay driver (and so CTest) fails on it.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace anisocert::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "anisocert fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void require(bool holds, const std::string& property) {
  if (!holds) finding(property);
}

}  // namespace anisocert::fuzz
