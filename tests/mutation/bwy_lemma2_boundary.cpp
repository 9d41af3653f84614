// Is there a rational G >= 1 and B > 0 with (G² − 1)(1 + G)²(1 + 4G)² B⁴ = 1, BWY Lemma 2's
// condition at equality? With G = 1 + t, u = t / (2 + t) ∈ [0, 1) the left factor is
// 16 u (5 + 3u)² / (1 − u)⁶, a rational fourth power only if u = v² and
// v (1 − v²)(5 + 3v²) is a rational square: a point of the genus-2 curve y² = v(1 − v²)(5 + 3v²)
// with 0 < v < 1 (finitely many by Faltings' theorem). For v = p/q in lowest terms the factors
// p, q, q − p, q + p, 5q² + 3p² are pairwise coprime but for the primes 2, 3, 5, so their product
// is a square exactly when each is s·k² with s | 30 and the s multiply to a square. This program
// searches every such p < q <= Q (docs/mutation.md, mutant 83).
//   g++ -std=c++20 -O2 tests/mutation/bwy_lemma2_boundary.cpp -o /tmp/bwy_lemma2_boundary && /tmp/bwy_lemma2_boundary 400000000
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric>

namespace {

using u64 = std::uint64_t;
constexpr u64 squarefree[] = {1, 2, 3, 5, 6, 10, 15, 30};

bool is_square(u64 n) {
  const u64 r = static_cast<u64>(std::sqrt(static_cast<long double>(n)));
  for (u64 k = r > 2 ? r - 2 : 0; k <= r + 2; ++k)
    if (k * k == n) return true;
  return false;
}

// The squarefree part of n when it divides 30, as a bit mask over {2, 3, 5}; −1 otherwise.
int part(u64 n) {
  for (u64 s : squarefree)
    if (n % s == 0 && is_square(n / s)) return (s % 2 == 0 ? 1 : 0) | (s % 3 == 0 ? 2 : 0) | (s % 5 == 0 ? 4 : 0);
  return -1;
}

}  // namespace

int main(int argc, char** argv) {
  const u64 Q = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  if (Q > 1000000000) {
    std::fprintf(stderr, "Q must be at most 10^9 (5q² + 3p² must fit in 64 bits)\n");
    return 2;
  }
  long candidates = 0, points = 0;
  for (u64 b : squarefree)
    for (u64 y = 1; b * y * y <= Q; ++y)
      for (u64 a : squarefree)
        for (u64 x = 1; a * x * x < b * y * y; ++x) {
          const u64 q = b * y * y, p = a * x * x;
          const int s3 = part(q - p), s4 = part(q + p);
          if (s3 < 0 || s4 < 0 || std::gcd(p, q) != 1) continue;
          const int s5 = part(5 * q * q + 3 * p * p);
          if (s5 < 0) continue;
          ++candidates;
          if ((part(p) ^ part(q) ^ s3 ^ s4 ^ s5) == 0) {
            ++points;
            std::printf("v = %llu/%llu\n", static_cast<unsigned long long>(p), static_cast<unsigned long long>(q));
          }
        }
  std::printf("q <= %llu: %ld candidates with every factor a square up to 2, 3, 5; %ld rational points\n",
              static_cast<unsigned long long>(Q), candidates, points);
}
