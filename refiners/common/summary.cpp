#include "refiners/common/summary.hpp"

#include <algorithm>
#include <sstream>

namespace anisocert::refiners::common {

namespace {

std::string size_text(const std::string& name, std::size_t vertices, std::size_t elements, const char* kind, double seconds) {
  std::ostringstream o;
  o << "  " << name << ": " << vertices << " vertices, " << elements << " " << kind << " in " << seconds << " s ("
    << static_cast<long>(vertices / std::max(seconds, 1e-9)) << " vertices/s)";
  return o.str();
}

}  // namespace

std::string size_line(const RefineResult& r, const std::string& name) {
  return size_text(name, r.mesh.sites.size(), r.mesh.triangles.size(), "triangles", r.seconds);
}

std::string size_line(const RefineResult3& r, const std::string& name) {
  return size_text(name, r.mesh.vertices.size(), r.mesh.tetrahedra.size(), "tetrahedra", r.seconds);
}

std::string stop_line(const RunOutcome& r, const std::string& unfinished) {
  std::string s = "  stopped: " + r.stop_reason;
  if (!r.consistent) s += "; last insertion by rule: " + r.last_rule + "; " + unfinished;
  return s;
}

std::string rule_counts_line(const RunOutcome& r) {
  std::string s = "  insertions by rule:";
  for (std::size_t k = 0; k < r.rule_counts.size(); ++k)
    s += " " + r.rule_counts[k].first + " " + std::to_string(r.rule_counts[k].second) + (k + 1 < r.rule_counts.size() ? "," : "");
  return s;
}

}  // namespace anisocert::refiners::common
