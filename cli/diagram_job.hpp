#pragma once
// Computing an exact diagram for a command (`diagram`, `demo`): the diagram with progress lines,
// its --json and --svg files (all written or none), the summary on standard output; exit 0, or 3
// when Theorem 7's preconditions hold and its conclusion fails (a bug or a counterexample).
#include "geometry/mesh.hpp"

#include <string>

namespace anisocert::cli {

struct DiagramOutputs {
  std::string json_path, svg_path;  // empty: not written
  bool quiet = false;
};

// `name` names the input in messages and the summary. A degenerate input the oracle declines
// is a UsageError naming it.
int compute_and_report_diagram(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o);

}  // namespace anisocert::cli
