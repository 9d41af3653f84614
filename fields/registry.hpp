#pragma once
// The metric fields by name (fields/registry.cpp lists them, one line each), in 2D and in 3D. A
// field is one file defining its entry: its name, its formula for --help and docs, its parameters
// with defaults, and how to build it from complete parameters (throwing std::invalid_argument,
// naming the parameter, for a value out of range).
#include "fields/metric_field.hpp"

#include <string>
#include <vector>

namespace anisocert::fields {

template <class Field>
struct Entry {
  std::string name;
  std::string formula;
  Parameters defaults;
  std::function<Field(const Parameters&)> make;
};
using FieldEntry = Entry<MetricField>;
using FieldEntry3 = Entry<MetricField3>;

const std::vector<FieldEntry>& builtin_fields();
const std::vector<FieldEntry3>& builtin_fields3();
std::vector<std::string> field_names();
std::vector<std::string> field_names3();

// The field `name` with `given` overriding its defaults. Throws std::invalid_argument naming an
// unknown field, an unknown parameter or a value out of range.
MetricField make_field(const std::string& name, const Parameters& given);
MetricField3 make_field3(const std::string& name, const Parameters& given);

// For FieldEntry::make: throw std::invalid_argument naming the parameter and the field.
void require_positive(const std::string& field, const Parameters& p, const char* name);
void require_non_negative(const std::string& field, const Parameters& p, const char* name);

}  // namespace anisocert::fields
