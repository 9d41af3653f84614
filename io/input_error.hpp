#pragma once
// Bad input: what() is one line naming the source (file name), the place (JSON path or index,
// line, byte) and what is wrong, e.g. "sites.json: sites[3].metric: metric [1, 2, 1] is not
// positive definite: ...". The CLI prints it and exits with code 2 (DESIGN.md § Command line).
#include <stdexcept>

namespace anisocert::io {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace anisocert::io
