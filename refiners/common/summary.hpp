#pragma once
// The lines every refiner's report shares (`anisocert refine`, the demo).
#include "refiners/common/result.hpp"

#include <string>

namespace anisocert::refiners::common {

// "  NAME: V vertices, T triangles in S s (R vertices/s)"
std::string size_line(const RefineResult& r, const std::string& name);
// "  NAME: V vertices, T tetrahedra in S s (R vertices/s)"
std::string size_line(const RefineResult3& r, const std::string& name);
// "  stopped: REASON", and when the output condition does not hold, the rule of the last insertion
// and what is left (`unfinished`, e.g. "inconsistent star triangles: 12").
std::string stop_line(const RunOutcome& r, const std::string& unfinished);
// "  insertions by rule: RULE N, …", in priority order.
std::string rule_counts_line(const RunOutcome& r);

}  // namespace anisocert::refiners::common
