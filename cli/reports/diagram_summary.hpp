#pragma once
// The text summary of an exact diagram (counts, orphans, the dual and its verdict, Theorem 7,
// timings): what `anisocert diagram` and `anisocert demo` print. The whole diagram is io/diagram_json.
#include "oracle/diagram/diagram.hpp"

#include <string>

namespace anisocert::cli {

std::string diagram_summary(const oracle::Diagram& d, const std::string& name);

}  // namespace anisocert::cli
