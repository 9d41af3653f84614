#include "predicates/filtered_sign.hpp"

#include <cstdio>

namespace anisocert::predicates {

void throw_non_finite(const char* predicate, const char* input, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%g", value);
  throw NonFiniteInput(std::string(predicate) + ": input " + input + " = " + text + " is not a finite number");
}

}  // namespace anisocert::predicates
