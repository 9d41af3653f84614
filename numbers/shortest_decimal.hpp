#pragma once
// The shortest decimal text that reads back as the double x (std::to_chars): how messages and
// reports name the refiners' doubles ("0.1", not the 55 digits of its exact expansion, which
// to_exact_string(rational_from_double(x)) gives).
#include <charconv>
#include <string>

namespace anisocert {

inline std::string shortest_decimal(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

}  // namespace anisocert
