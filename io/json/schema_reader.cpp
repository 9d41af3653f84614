#include "io/json/schema_reader.hpp"

#include "numbers/excerpt.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace anisocert::io {

namespace {

// Whether v nests containers more than `limit` deep, found without recursion.
bool deeper_than(const nlohmann::json& v, int limit) {
  std::vector<std::pair<const nlohmann::json*, int>> todo{{&v, 0}};
  while (!todo.empty()) {
    const auto [j, depth] = todo.back();
    todo.pop_back();
    if (depth > limit) return true;
    if (j->is_structured())
      for (const auto& child : *j) todo.push_back({&child, depth + 1});
  }
  return false;
}

}  // namespace

std::string show(const nlohmann::json& v) {
  // A deeply nested container is named by its size, not dumped: dumping recurses once per level,
  // and a hostile file nests arrays tens of thousands deep.
  if (deeper_than(v, 32))
    return std::string(v.is_array() ? "an array" : "an object") + " nested more than 32 deep, of " + std::to_string(v.size()) +
           " entries";
  // One line of ASCII (control characters and non-ASCII as JSON escapes), an excerpt of about 60.
  const std::string s = v.dump(-1, ' ', true);
  return excerpt(s, s.size() <= 60 ? 60 : 57);
}

std::string indexed(const std::string& name, std::size_t i) { return name + "[" + std::to_string(i) + "]"; }

void SchemaReader::fail(const std::string& path, const std::string& what) const {
  throw InputError(source_ + ": " + (path.empty() ? "" : path + ": ") + what);
}

void SchemaReader::require_keys(const Json& object, const std::string& path, std::initializer_list<const char*> required,
                                std::initializer_list<const char*> allowed) const {
  std::string expected;
  for (const char* k : allowed) expected += (expected.empty() ? "" : ", ") + std::string(k);
  for (const auto& item : object.items())
    if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
      fail(path, "unknown key " + show(Json(item.key())) + " (expected " + expected + ")");
  for (const char* k : required)
    if (!object.contains(k)) fail(path, "missing key \"" + std::string(k) + "\"");
}

Rational SchemaReader::number(const Json& v, const std::string& path) const {
  if (v.is_number_unsigned()) return Rational(Integer(v.get<std::uint64_t>()));
  if (v.is_number_integer()) return Rational(Integer(v.get<std::int64_t>()));
  if (!v.is_string())
    fail(path, "expected a number (a JSON number, or a string holding an integer, fraction or decimal), got " + show(v));
  try {
    return parse_input_number(v.get_ref<const std::string&>());
  } catch (const NumberSyntaxError& e) {
    fail(path, e.what());
  }
}

std::vector<Rational> SchemaReader::numbers(const Json& v, std::size_t n, const std::string& path,
                                            const std::string& expected) const {
  if (!v.is_array() || v.size() != n) fail(path, "expected " + expected + ", got " + show(v));
  std::vector<Rational> q;
  for (std::size_t i = 0; i < n; ++i) q.push_back(number(v[i], indexed(path, i)));
  return q;
}

std::vector<int> SchemaReader::indices(const Json& s, std::size_t count, std::size_t n, const std::string& path,
                                       const char* what, bool vertices) const {
  if (!s.is_array() || s.size() != count) fail(path, std::string("expected ") + what + ", got " + show(s));
  std::vector<int> ends;
  for (std::size_t e = 0; e < count; ++e) {
    if (!s[e].is_number_unsigned() || s[e].get<std::uint64_t>() >= n)
      fail(indexed(path, e), std::string("expected a ") + (vertices ? "vertex" : "site") + " index from 0 to " + std::to_string(n - 1) +
                                 ", got " + show(s[e]));
    const int v = static_cast<int>(s[e].get<std::uint64_t>());
    if (std::find(ends.begin(), ends.end(), v) != ends.end())
      fail(path, "repeats " + (vertices ? "vertex " + std::to_string(v) : indexed("sites", v)));
    ends.push_back(v);
  }
  return ends;
}

}  // namespace anisocert::io
