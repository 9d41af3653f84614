#pragma once
// A metric field (x, y) ↦ M(x, y), symmetric positive definite, in floating point: what the
// refiners mesh for (unit length in M is the intended edge length), the demo samples and the
// benchmarks drive. Refiners are fast, not exact; their output is judged by the exact certifier.
// Its 3D twin (x, y, z) ↦ M(x, y, z) (MetricField3) is what tetrahedral meshes are certified
// against (the UGAWG benchmark's fields).
#include "predicates/point.hpp"

#include <functional>
#include <map>
#include <stdexcept>
#include <string>

namespace anisocert::fields {

using Parameters = std::map<std::string, double>;

struct MetricField {
  std::string name;
  Parameters params;  // every parameter, defaults filled in
  std::function<predicates::Sym2<double>(double, double)> at;  // may throw FieldError (below)
};

struct MetricField3 {
  std::string name;
  Parameters params;
  std::function<predicates::Sym3<double>(double, double, double)> at;  // may throw FieldError (below)
};

// A field with no metric at a point it is asked about (a background mesh that does not cover it),
// or whose metric there is not finite and positive definite: what() names the field and the
// point. The refiners let it through; the CLI turns it into exit 2.
struct FieldError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

}  // namespace anisocert::fields
