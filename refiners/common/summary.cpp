#include "refiners/common/summary.hpp"

#include <algorithm>
#include <sstream>

namespace anisocert::refiners::common {

std::string size_line(const RefineResult& r, const std::string& name) {
  std::ostringstream o;
  o << "  " << name << ": " << r.mesh.sites.size() << " vertices, " << r.mesh.triangles.size() << " triangles in " << r.seconds
    << " s (" << static_cast<long>(r.mesh.sites.size() / std::max(r.seconds, 1e-9)) << " vertices/s)";
  return o.str();
}

std::string stop_line(const RefineResult& r, const std::string& unfinished) {
  std::string s = "  stopped: " + r.stop_reason;
  if (!r.consistent) s += "; last insertion by rule: " + r.last_rule + "; " + unfinished;
  return s;
}

std::string rule_counts_line(const RefineResult& r) {
  std::string s = "  insertions by rule:";
  for (std::size_t k = 0; k < r.rule_counts.size(); ++k)
    s += " " + r.rule_counts[k].first + " " + std::to_string(r.rule_counts[k].second) + (k + 1 < r.rule_counts.size() ? "," : "");
  return s;
}

}  // namespace anisocert::refiners::common
