#pragma once
// Reading a schema out of an exact JSON document (json/exact_document.hpp): every failure is one
// InputError naming the source, the JSON path ("sites[3].metric[1]") and what was expected.
#include "io/input_error.hpp"
#include "numbers/rational.hpp"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <vector>

namespace anisocert::io {

class SchemaReader {
 public:
  using Json = nlohmann::json;
  explicit SchemaReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  // Unknown keys and missing required ones are errors.
  void require_keys(const Json& object, const std::string& path, std::initializer_list<const char*> required,
                    std::initializer_list<const char*> allowed) const;
  // A JSON number, or a string holding an integer, fraction or decimal, exactly; within the
  // magnitudes anisocert reads (numbers/rational.hpp: parse_input_number).
  Rational number(const Json& v, const std::string& path) const;
  // An array of exactly n numbers; `expected` names the shape in messages ("[m11, m12, m22]").
  std::vector<Rational> numbers(const Json& v, std::size_t n, const std::string& path, const std::string& expected) const;
  // An array of `count` distinct indices from 0 to n − 1 (`what` names the shape in messages).
  // vertices: the indices are of a domain's vertices (its corners, then its points), not of "sites".
  std::vector<int> indices(const Json& v, std::size_t count, std::size_t n, const std::string& path, const char* what,
                           bool vertices = false) const;

 private:
  std::string source_;
};

// The JSON text of v on one line of ASCII (other characters as \uXXXX), cut after about 60
// characters.
std::string show(const nlohmann::json& v);
// "name[i]"
std::string indexed(const std::string& name, std::size_t i);

}  // namespace anisocert::io
