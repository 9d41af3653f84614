#include "fields/registry.hpp"

#include "fields/builtin.hpp"
#include "numbers/excerpt.hpp"

#include <cmath>
#include <stdexcept>

namespace anisocert::fields {

const std::vector<FieldEntry>& builtin_fields() {
  static const std::vector<FieldEntry> fields = {
      constant_field(),
      linear_field(),
      shock_field(),
      radial_field(),
  };
  return fields;
}

const std::vector<FieldEntry3>& builtin_fields3() {
  static const std::vector<FieldEntry3> fields = {
      constant_field3(),
      ugawg_linear_field(),
      ugawg_polar_field(1),
      ugawg_polar_field(2),
  };
  return fields;
}

namespace {

template <class Field>
std::vector<std::string> names_of(const std::vector<Entry<Field>>& entries) {
  std::vector<std::string> names;
  for (const auto& f : entries) names.push_back(f.name);
  return names;
}

template <class Field>
Field make(const std::vector<Entry<Field>>& entries, const std::string& name, const Parameters& given, const char* dimension) {
  for (const auto& f : entries) {
    if (f.name != name) continue;
    Parameters p = f.defaults;
    for (const auto& [k, v] : given) {
      if (!p.count(k)) throw std::invalid_argument("field " + name + " has no parameter " + quoted_excerpt(k));
      if (!std::isfinite(v)) throw std::invalid_argument("parameter " + k + " must be finite");
      p[k] = v;
    }
    return f.make(p);
  }
  std::string known;
  for (const std::string& n : names_of(entries)) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown " + std::string(dimension) + " field " + quoted_excerpt(name) + " (" + known + ")");
}

}  // namespace

std::vector<std::string> field_names() { return names_of(builtin_fields()); }
std::vector<std::string> field_names3() { return names_of(builtin_fields3()); }

MetricField make_field(const std::string& name, const Parameters& given) { return make(builtin_fields(), name, given, "2D"); }
MetricField3 make_field3(const std::string& name, const Parameters& given) { return make(builtin_fields3(), name, given, "3D"); }

void require_positive(const std::string& field, const Parameters& p, const char* name) {
  if (!(p.at(name) > 0))
    throw std::invalid_argument("parameter " + std::string(name) + " of field " + field + " must be positive");
}

void require_non_negative(const std::string& field, const Parameters& p, const char* name) {
  if (p.at(name) < 0) throw std::invalid_argument("parameter " + std::string(name) + " of field " + field + " must be >= 0");
}

}  // namespace anisocert::fields
