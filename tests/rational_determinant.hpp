#pragma once
// The determinant of a square rational matrix by Gaussian elimination: the tests' own, written
// apart from the predicates' kernels so that the tests that use it check them independently.
#include "numbers/rational.hpp"

#include <utility>
#include <vector>

namespace anisocert::testing {

inline Rational determinant(std::vector<std::vector<Rational>> a) {
  const std::size_t n = a.size();
  Rational det = 1;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    while (pivot < n && a[pivot][c] == 0) ++pivot;
    if (pivot == n) return 0;
    if (pivot != c) std::swap(a[pivot], a[c]), det = -det;
    det *= a[c][c];
    for (std::size_t r = c + 1; r < n; ++r) {
      const Rational f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  return det;
}

}  // namespace anisocert::testing
