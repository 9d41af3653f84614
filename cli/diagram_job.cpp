#include "cli/diagram_job.hpp"

#include "cli/output.hpp"
#include "cli/reports/diagram_summary.hpp"
#include "cli/usage_error.hpp"
#include "io/diagram_json.hpp"
#include "io/svg/diagram_svg.hpp"

#include <iostream>

namespace anisocert::cli {

int compute_and_report_diagram(const geometry::Mesh<Rational>& in, const std::string& name, const DiagramOutputs& o) {
  const auto progress = progress_printer(o.quiet);
  oracle::Diagram d;
  try {
    d = oracle::compute_diagram(in, progress);
  } catch (const std::domain_error& e) {  // a degenerate input the oracle declines, named
    throw UsageError(name + ": " + e.what());
  }
  std::string json, svg;
  if (!o.json_path.empty()) json = io::diagram_json(d).dump(1) + "\n";
  if (!o.svg_path.empty()) svg = io::diagram_svg(d);
  if (!o.json_path.empty()) write_file_atomically(o.json_path, json);
  if (!o.svg_path.empty()) write_file_atomically(o.svg_path, svg);
  std::string text = diagram_summary(d, name);
  if (!o.svg_path.empty()) text += "  picture: " + o.svg_path + "\n";
  if (d.theorem7.disagreement) {
    std::cerr << "anisocert: THEOREM 7 DISAGREEMENT: its preconditions hold but the dual is not a triangulation of Ω.\n"
                 "This is a bug in the oracle or a counterexample to LS Theorem 7; please report the input.\n";
    emit(text);
    return 3;
  }
  emit(text);
  return 0;
}

}  // namespace anisocert::cli
