#pragma once
// The bad inputs a refinement run can meet, each named in what() (the CLI turns them into exit 2).
#include "fields/metric_field.hpp"

#include <stdexcept>

namespace anisocert::refiners::common {

// A domain a refiner cannot use: the corner or the edge, and why.
struct DomainError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A metric field that is not finite and positive definite where a site is inserted (the field,
// the point and the metric), or that has no value where it is sampled (fields/metric_field.hpp).
using FieldError = fields::FieldError;

}  // namespace anisocert::refiners::common
