#pragma once
// Bad input or usage: main prints the message on one line and exits with code 2
// (DESIGN.md § Command line and files).

#include <stdexcept>

namespace anisocert::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace anisocert::cli
