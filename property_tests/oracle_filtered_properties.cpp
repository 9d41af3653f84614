// Issue 14: the oracle's filtered constructions (certified interval roots and sample points,
// exact points built only on demand) and its threads only speed it up. On random inputs the
// diagram built with filters, on one thread and on two, is the one built exactly
// (DiagramOptions::exact_only): the whole JSON apart from `stats` (timings, filter counts). The
// inputs are the oracle's property-test cases: sites on a 1/64 grid with constant, nearly
// constant or varied metrics (constant metrics make exact ties common: cocircular sites, vertices
// on ∂Ω and on wedge lines, bisectors through corners), and the Theorem 7 cases with sites on ∂Ω.
#include "io/diagram_json.hpp"
#include "property_tests/generators/diagram_inputs.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

using anisocert::Rational;
using namespace anisocert::oracle;
using namespace anisocert::gen;

namespace {

// The JSON without its stats, or the message of a declined input.
std::string outcome(const Mesh<Rational>& in, bool exact_only, int threads, FilterCounts* counts = nullptr) {
  DiagramOptions o;
  o.exact_only = exact_only, o.threads = threads;
  try {
    const Diagram d = compute_diagram(in, o);
    if (counts) *counts = d.stats.filters;
    anisocert::io::OrderedJson j = anisocert::io::diagram_json(d);
    j.erase("stats");
    return j.dump();
  } catch (const std::domain_error& e) {
    return std::string("declined: ") + e.what();
  }
}

}  // namespace

RC_GTEST_PROP(Oracle_Filters, FilteredDiagramIsTheExactOne, ()) {
  const DiagramCase c = *rc::gen::oneOf(diagram_case(), theorem7_case());
  RC_TAG(c.kind);
  const std::string exact = outcome(c.input, true, 1);
  FilterCounts counts;
  const std::string filtered = outcome(c.input, false, 1, &counts);
  if (exact.rfind("declined", 0) == 0) RC_TAG("declined");
  if (counts.roots_exact > 0) RC_TAG("some roots exact (tangencies, shared components)");
  if (counts.signs_exact > 0) RC_TAG("some signs exact (ties)");
  RC_ASSERT(filtered == exact);
  RC_ASSERT(outcome(c.input, false, 2) == exact);
}
