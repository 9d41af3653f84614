#pragma once
// What every format's test asks of a reader: the message of the InputError it throws, and a fresh
// folder for the files a writer produces.
#include "io/input_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace anisocert::test_support {

// The message of the InputError f throws; "" when it throws none.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

// An empty folder under the test temporary directory.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace anisocert::test_support
