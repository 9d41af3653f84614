#include "io/json/exact_document.hpp"

#include "numbers/excerpt.hpp"

#include <utility>
#include <vector>

namespace anisocert::io {
namespace {

using Json = nlohmann::json;

// Builds the document like nlohmann's own DOM parser, with the two differences of the header.
class ExactDocument : public nlohmann::json_sax<Json> {
 public:
  explicit ExactDocument(const std::string& source) : source_(source) {}
  Json take() { return std::move(root_); }

  bool null() override { return add(nullptr); }
  bool boolean(bool b) override { return add(b); }
  bool number_integer(number_integer_t n) override { return add(n); }
  bool number_unsigned(number_unsigned_t n) override { return add(n); }
  bool number_float(number_float_t, const string_t& lexeme) override { return add(lexeme); }
  bool string(string_t& s) override { return add(std::move(s)); }
  bool binary(binary_t& b) override { return add(Json::binary(std::move(b))); }
  bool start_object(std::size_t) override { return open(Json::object()); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    if (open_.back()->contains(k)) {
      const std::string where = path();
      throw InputError(source_ + ": " + (where.empty() ? "" : where + ": ") + "key " + quoted_excerpt(k) +
                       " appears twice");
    }
    keys_.back() = std::move(k);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& e) override {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at line 1, ...; last read: '...'"
    if (const auto end_of_id = what.find("] "); end_of_id != std::string::npos) what.erase(0, end_of_id + 2);
    // nlohmann quotes the last token read whole ("last read: '...'", "number overflow parsing
    // '...'"): a string or a number of a megabyte would be, so it is cut.
    const std::string quoted = "'" + last_token + "'";
    if (const auto at = what.find(quoted); at != std::string::npos) what.replace(at, quoted.size(), "'" + excerpt(last_token) + "'");
    throw InputError(source_ + ": invalid JSON at byte " + std::to_string(position) + ": " + what);
  }

 private:
  // Places v in the innermost open container (or as the root) and returns where it now lives.
  // Pointers to open containers stay valid: only the innermost one grows.
  Json* place(Json v) {
    if (open_.empty()) return &(root_ = std::move(v));
    Json& container = *open_.back();
    if (container.is_array()) {
      container.push_back(std::move(v));
      return &container.back();
    }
    return &(container[keys_.back()] = std::move(v));
  }
  bool add(Json v) {
    place(std::move(v));
    return true;
  }
  bool open(Json empty) {
    open_.push_back(place(std::move(empty)));
    keys_.emplace_back();
    return true;
  }
  bool close() {
    open_.pop_back();
    keys_.pop_back();
    return true;
  }
  // The path of the innermost open container, "sites[3]" style, each key an excerpt; past 32
  // levels, its depth instead (a hostile file nests tens of thousands).
  std::string path() const {
    if (open_.size() > 33) return "a value nested " + std::to_string(open_.size() - 1) + " deep";
    std::string p;
    for (std::size_t k = 0; k + 1 < open_.size(); ++k)
      p += open_[k]->is_array() ? "[" + std::to_string(open_[k]->size() - 1) + "]"
                                : (p.empty() ? "" : ".") + excerpt(keys_[k]);
    return p;
  }

  std::string source_;
  Json root_;
  std::vector<Json*> open_;        // the containers being filled, outermost first
  std::vector<std::string> keys_;  // per open object, the key of the value being filled
};

}  // namespace

nlohmann::json parse_exact_json(std::istream& in, const std::string& source) {
  ExactDocument document(source);
  Json::sax_parse(in, &document);  // throws InputError on malformed JSON
  return document.take();
}

}  // namespace anisocert::io
