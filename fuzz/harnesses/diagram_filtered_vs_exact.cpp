// The oracle's filtered constructions against its exact ones (issue 14; docs/oracle.md § Filters),
// on the small inputs of fuzz/support/small_diagram.hpp (up to 6 sites on the grid of eighths,
// metrics up to 4:1, a square, a triangle or an L-shaped domain; ties, cocircular sites and sites
// on ∂Ω are common):
//   - the diagram built with filters on one thread, and on two, is the one built exactly
//     (DiagramOptions::exact_only): the same JSON apart from `stats` (timings and filter counts);
//   - an input the exact path declines (std::domain_error) is declined with the same message;
//     any other exception is a finding.
// Limit: 2 + 5·6 bytes.
#include "fuzz/support/finding.hpp"
#include "fuzz/support/small_diagram.hpp"
#include "io/diagram_json.hpp"

#include <stdexcept>
#include <string>

using anisocert::fuzz::require;
namespace oracle = anisocert::oracle;

namespace {

std::string outcome(const anisocert::geometry::Mesh<anisocert::Rational>& in, bool exact_only, int threads) {
  oracle::DiagramOptions o;
  o.exact_only = exact_only, o.threads = threads;
  try {
    anisocert::io::OrderedJson j = anisocert::io::diagram_json(oracle::compute_diagram(in, o));
    j.erase("stats");
    return j.dump();
  } catch (const std::domain_error& e) {
    return std::string("declined: ") + e.what();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > anisocert::fuzz::small_diagram_max_len) return -1;
  const anisocert::fuzz::SmallDiagram small = anisocert::fuzz::small_diagram(data, size);
  if (small.input.sites.empty()) return 0;
  const std::string exact = outcome(small.input, true, 1);
  require(outcome(small.input, false, 1) == exact, "the filtered diagram (one thread) differs from the exact one");
  require(outcome(small.input, false, 2) == exact, "the filtered diagram (two threads) differs from the exact one");
  return 0;
}
