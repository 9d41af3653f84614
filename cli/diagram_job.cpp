#include "cli/diagram_job.hpp"

#include "cli/reports/diagram_summary.hpp"
#include "cli/usage_error.hpp"
#include "io/diagram_json.hpp"
#include "io/svg/diagram_svg.hpp"

#include <iostream>

namespace anisocert::cli {

oracle::Diagram exact_diagram(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o) {
  try {
    oracle::DiagramOptions options;
    options.exact_only = o.exact_only;
    options.threads = o.threads;
    if (const auto print = progress_printer(o.quiet))
      options.progress = [print, label = o.progress_label](const std::string& line) { print(label + line); };
    return oracle::compute_diagram(in, options);
  } catch (const std::domain_error& e) {  // a degenerate input the oracle declines, named
    throw UsageError(name + ": " + e.what());
  }
}

int theorem7_exit_code(const oracle::Diagram& d) {
  if (!d.theorem7.disagreement) return 0;
  std::cerr << "anisocert: THEOREM 7 DISAGREEMENT: its preconditions hold but the dual is not a triangulation of Ω.\n"
               "This is a bug in the oracle or a counterexample to LS Theorem 7; please report the input.\n";
  return 3;
}

DiagramJob diagram_job(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o) {
  const oracle::Diagram d = exact_diagram(in, name, o);
  DiagramJob job;
  if (!o.json_path.empty()) job.files.push_back({o.json_path, io::diagram_json(d).dump(1) + "\n"});
  if (!o.svg_path.empty()) job.files.push_back({o.svg_path, io::diagram_svg(d)});
  job.text = diagram_summary(d, name);
  if (!o.svg_path.empty()) job.text += "  picture: " + o.svg_path + "\n";
  job.exit_code = theorem7_exit_code(d);
  return job;
}

}  // namespace anisocert::cli
