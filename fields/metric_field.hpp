#pragma once
// A metric field (x, y) ↦ M(x, y), symmetric positive definite, in floating point: what the
// refiners mesh for (unit length in M is the intended edge length), the demo samples and the
// benchmarks drive. Refiners are fast, not exact; their output is judged by the exact certifier.
#include "predicates/point.hpp"

#include <functional>
#include <map>
#include <string>

namespace anisocert::fields {

using Parameters = std::map<std::string, double>;

struct MetricField {
  std::string name;
  Parameters params;  // every parameter, defaults filled in
  std::function<predicates::Sym2<double>(double, double)> at;
};

}  // namespace anisocert::fields
