#include "cli/reports/refine_report.hpp"

namespace anisocert::cli {

std::string report_text(const refiners::Run& run) {
  std::string text;
  for (const std::string& line : run.report) text += line + "\n";
  return text;
}

}  // namespace anisocert::cli
