#include "refiners/registry.hpp"

#include "refiners/bwy/entry.hpp"
#include "refiners/ls/entry.hpp"
#include "refiners/star/entry.hpp"

namespace anisocert::refiners {

const std::vector<RefinerEntry>& registered_refiners() {
  static const std::vector<RefinerEntry> entries = {
      star::entry(),
      ls::entry(),
      bwy::entry(),
  };
  return entries;
}

std::vector<std::string> refiner_names() {
  std::vector<std::string> names;
  for (const RefinerEntry& e : registered_refiners()) names.push_back(e.name);
  return names;
}

const RefinerEntry* find_refiner(const std::string& name) {
  for (const RefinerEntry& e : registered_refiners())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace anisocert::refiners
