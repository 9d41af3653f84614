#pragma once
// Computing an exact diagram for a command (`diagram`, `demo`): the diagram with progress lines,
// its --json and --svg files and the summary, for the command to write (all files or none) and
// print; exit 0, or 3 when Theorem 7's preconditions hold and its conclusion fails (a bug or a
// counterexample, also said on standard error).
#include "cli/output.hpp"
#include "geometry/mesh.hpp"
#include "oracle/diagram/diagram.hpp"

#include <string>
#include <vector>

namespace anisocert::cli {

struct DiagramOutputs {
  std::string json_path, svg_path;  // empty: not written
  bool quiet = false;
  bool exact_only = false;  // build every point exactly, no filtered constructions
  int threads = 0;          // 0: every core
  std::string progress_label = "";  // before each progress line (refine's "--svg: ")
};

struct DiagramJob {
  std::string text;
  std::vector<OutputFile> files;
  int exit_code = 0;
};

// The exact diagram with progress lines (unless quiet), exact-only and threads as asked; a
// degenerate input the oracle declines is a UsageError naming `name`.
oracle::Diagram exact_diagram(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o);

// 3 after saying so on standard error when Theorem 7's preconditions hold and its conclusion
// fails (a bug or a counterexample); else 0.
int theorem7_exit_code(const oracle::Diagram& d);

// `name` names the input in messages and the summary. A degenerate input the oracle declines
// is a UsageError naming it.
DiagramJob diagram_job(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o);

}  // namespace anisocert::cli
