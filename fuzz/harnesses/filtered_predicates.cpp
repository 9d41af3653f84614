// Filtered against exact (docs/fuzzing.md § Differential; DESIGN.md: filters only speed up, never
// change, an answer). The first byte picks a check, the 8-byte slots after it are its doubles
// (missing ones are 0):
//   0-8  a predicate kernel: filtered_sign on the doubles and on their rationals must equal
//        exact_sign on the rationals; with a NaN or an infinity among the inputs the filter must
//        decline (NonFiniteInput), never answer;
//   9    sign_of_root_sum(x, y, X) against the closed form (signs of x and y√X, then x² − y²X);
//   10   FilterInterval::around(a/b) must contain a/b (the oracle's and certifier's enclosures).
// The structure-aware mutator (fuzz/support/geometric_mutator.hpp) writes ties and hostile values
// into the slots. Limit: 1 + 8·16 bytes.
#include "fuzz/support/finding.hpp"
#include "fuzz/support/geometric_mutator.hpp"
#include "predicates/angle.hpp"
#include "predicates/bisector.hpp"
#include "predicates/distortion.hpp"
#include "predicates/incircle.hpp"
#include "predicates/length_compare.hpp"
#include "predicates/metric_dot.hpp"
#include "predicates/orientation.hpp"
#include "predicates/sqrt_sign.hpp"

#include <cmath>
#include <string>

using anisocert::Rational;
using anisocert::Sign;
using anisocert::fuzz::require;
namespace pr = anisocert::predicates;

namespace {

constexpr std::size_t header = 1, max_slots = 16;

double slot(const std::vector<double>& s, std::size_t i) { return i < s.size() ? s[i] : 0.0; }

template <class K>
void check_kernel(const std::vector<double>& s) {
  std::array<double, K::arity> x{};
  bool finite = true;
  for (std::size_t i = 0; i < K::arity; ++i) x[i] = slot(s, i), finite = finite && std::isfinite(x[i]);
  if (!finite) {
    try {
      (void)pr::filtered_sign<K>(x);
    } catch (const pr::NonFiniteInput&) {
      return;
    }
    anisocert::fuzz::finding(std::string(K::name) + ": the filter answered a sign for a NaN or infinite input");
  }
  std::array<Rational, K::arity> q;
  for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
  const Sign exact = pr::exact_sign<K>(q);
  require(pr::filtered_sign<K>(x) == exact, std::string(K::name) + ": the filtered sign on doubles differs from the exact sign");
  require(pr::filtered_sign<K>(q) == exact, std::string(K::name) + ": the filtered sign on rationals differs from the exact sign");
}

int sgn(const Rational& q) { return q > 0 ? 1 : q < 0 ? -1 : 0; }

// sign(x + y√X), X ≥ 0, from its definition: the signs of the two terms, and when they differ the
// sign of x² − y²X with the sign of x.
void check_root_sum(const std::vector<double>& s) {
  for (std::size_t i = 0; i < 3; ++i)
    if (!std::isfinite(slot(s, i))) return;
  const Rational x(slot(s, 0)), y(slot(s, 1)), X(abs(Rational(slot(s, 2))));
  const int a = sgn(x), b = X == 0 ? 0 : sgn(y);
  const int expected = a == 0 ? b : b == 0 || a == b ? a : a * sgn(x * x - y * y * X);
  require(static_cast<int>(pr::sign_of_root_sum(x, y, X)) == expected, "sign_of_root_sum(x, y, X) differs from its closed form");
}

void check_enclosure(const std::vector<double>& s) {
  const double a = slot(s, 0), b = slot(s, 1);
  if (!std::isfinite(a) || !std::isfinite(b) || b == 0) return;
  const Rational q = Rational(a) / Rational(b);
  const anisocert::FilterInterval e = anisocert::FilterInterval::around(q);
  require(!(e.lo > e.hi), "FilterInterval::around gave an empty interval");
  require((std::isinf(e.lo) || Rational(e.lo) <= q) && (std::isinf(e.hi) || q <= Rational(e.hi)),
          "FilterInterval::around(a/b) does not contain a/b");
}

}  // namespace

ANISOCERT_GEOMETRIC_MUTATOR(header)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < header || size > header + 8 * max_slots) return -1;
  const std::vector<double> s = anisocert::fuzz::slots_of(data, size, header);
  switch (data[0] % 11) {
    case 0: check_kernel<pr::OrientationKernel>(s); break;
    case 1: check_kernel<pr::InCircleKernel>(s); break;
    case 2: check_kernel<pr::SideOfBisectorKernel>(s); break;
    case 3: check_kernel<pr::AngleCosKernel>(s); break;
    case 4: check_kernel<pr::AngleSinKernel>(s); break;
    case 5: check_kernel<pr::ScaledDifferenceDiagonalKernel>(s); break;
    case 6: check_kernel<pr::ScaledDifferenceDeterminantKernel>(s); break;
    case 7: check_kernel<pr::MetricDotKernel>(s); break;
    case 8: check_kernel<pr::ScaledLengthCompareKernel>(s); break;
    case 9: check_root_sum(s); break;
    default: check_enclosure(s); break;
  }
  return 0;
}
