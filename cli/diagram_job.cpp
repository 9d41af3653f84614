#include "cli/diagram_job.hpp"

#include "cli/reports/diagram_summary.hpp"
#include "cli/usage_error.hpp"
#include "io/diagram_json.hpp"
#include "io/svg/diagram_svg.hpp"

#include <iostream>

namespace anisocert::cli {

DiagramJob diagram_job(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o) {
  oracle::Diagram d;
  try {
    oracle::DiagramOptions options;
    options.exact_only = o.exact_only;
    options.threads = o.threads;
    options.progress = progress_printer(o.quiet);
    d = oracle::compute_diagram(in, options);
  } catch (const std::domain_error& e) {  // a degenerate input the oracle declines, named
    throw UsageError(name + ": " + e.what());
  }
  DiagramJob job;
  if (!o.json_path.empty()) job.files.push_back({o.json_path, io::diagram_json(d).dump(1) + "\n"});
  if (!o.svg_path.empty()) job.files.push_back({o.svg_path, io::diagram_svg(d)});
  job.text = diagram_summary(d, name);
  if (!o.svg_path.empty()) job.text += "  picture: " + o.svg_path + "\n";
  if (d.theorem7.disagreement) {
    std::cerr << "anisocert: THEOREM 7 DISAGREEMENT: its preconditions hold but the dual is not a triangulation of Ω.\n"
                 "This is a bug in the oracle or a counterexample to LS Theorem 7; please report the input.\n";
    job.exit_code = 3;
  }
  return job;
}

}  // namespace anisocert::cli
