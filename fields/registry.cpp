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

std::vector<std::string> field_names() {
  std::vector<std::string> names;
  for (const FieldEntry& f : builtin_fields()) names.push_back(f.name);
  return names;
}

MetricField make_field(const std::string& name, const Parameters& given) {
  for (const FieldEntry& f : builtin_fields()) {
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
  for (const std::string& n : field_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown field " + quoted_excerpt(name) + " (" + known + ")");
}

void require_positive(const std::string& field, const Parameters& p, const char* name) {
  if (!(p.at(name) > 0))
    throw std::invalid_argument("parameter " + std::string(name) + " of field " + field + " must be positive");
}

void require_non_negative(const std::string& field, const Parameters& p, const char* name) {
  if (p.at(name) < 0) throw std::invalid_argument("parameter " + std::string(name) + " of field " + field + " must be >= 0");
}

}  // namespace anisocert::fields
