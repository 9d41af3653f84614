#include "io/formats/text_reader.hpp"

#include <fstream>
#include <sstream>

namespace anisocert::io {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// A token as a message shows it: printable ASCII kept, other bytes as \xNN, at most 40 characters.
std::string shown(std::string_view t) {
  std::string s;
  for (std::size_t i = 0; i < t.size() && s.size() < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(t[i]);
    if (c >= 0x20 && c < 0x7f) {
      s += static_cast<char>(c);
    } else {
      const char* hex = "0123456789abcdef";
      s += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
  }
  return t.size() > s.size() && s.size() >= 40 ? s + "..." : s;
}

}  // namespace

TextReader::TextReader(std::string_view text, std::string source, char comment)
    : text_(text), source_(std::move(source)), comment_(comment) {}

void TextReader::skip_blanks() {
  while (at_ < text_.size()) {
    const char c = text_[at_];
    if (c == '\n') {
      ++line_, ++at_;
    } else if (blank(c)) {
      ++at_;
    } else if (comment_ != '\0' && c == comment_) {
      while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    } else {
      return;
    }
  }
}

bool TextReader::at_end() {
  skip_blanks();
  return at_ >= text_.size();
}

std::string_view TextReader::peek() {
  skip_blanks();
  std::size_t end = at_;
  while (end < text_.size() && !blank(text_[end]) && !(comment_ != '\0' && text_[end] == comment_)) ++end;
  return text_.substr(at_, end - at_);
}

std::string_view TextReader::token(std::string_view what) {
  const std::string_view t = peek();
  if (t.empty()) {
    line_ = token_line_;  // the end of the file is reported at its last token
    fail("the file ends where " + std::string(what) + " was expected");
  }
  at_ += t.size();
  token_line_ = line_;
  return t;
}

void TextReader::expect(std::string_view keyword) {
  const std::string_view t = token("\"" + std::string(keyword) + "\"");
  if (t != keyword) fail("expected \"" + std::string(keyword) + "\", found \"" + shown(t) + "\"");
}

std::int64_t TextReader::integer(std::string_view what, std::int64_t lo, std::int64_t hi) {
  const std::string_view t = token(what);
  std::size_t i = 0;
  bool negative = false;
  if (t[0] == '+' || t[0] == '-') negative = t[0] == '-', i = 1;
  if (i == t.size()) fail(std::string(what) + ": \"" + shown(t) + "\" is not an integer");
  std::int64_t v = 0;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (c < '0' || c > '9') fail(std::string(what) + ": \"" + shown(t) + "\" is not an integer");
    if (v > (INT64_MAX - (c - '0')) / 10) fail(std::string(what) + ": " + shown(t) + " is out of range");
    v = v * 10 + (c - '0');
  }
  if (negative) v = -v;
  if (v < lo || v > hi)
    fail(std::string(what) + " is " + std::string(t) + ", outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

Rational TextReader::number(std::string_view what) {
  const std::string_view t = token(what);
  try {
    Rational q = parse_rational(t);
    // Magnitudes far beyond the doubles' (1e100000 is a valid decimal) are no mesh's: every
    // predicate on them would fall to exact arithmetic on huge integers. Refused, not rounded.
    const long bits = static_cast<long>(mpz_sizeinbase(mpq_numref(q.backend().data()), 2)) -
                      static_cast<long>(mpz_sizeinbase(mpq_denref(q.backend().data()), 2));
    if (q != 0 && (bits > max_magnitude_bits || bits < -max_magnitude_bits))
      fail(std::string(what) + ": \"" + shown(t) + "\" is outside the magnitudes a mesh file may hold (2^-" +
           std::to_string(max_magnitude_bits) + " to 2^" + std::to_string(max_magnitude_bits) + ", past the doubles')");
    return q;
  } catch (const NumberSyntaxError& e) {
    const std::string why = e.what();
    const auto k = why.find("is not an exact number");
    fail(std::string(what) + ": \"" + shown(t) + "\" " + (k == std::string::npos ? why : why.substr(k)));
  }
}

std::string_view TextReader::rest_of_line() {
  while (at_ < text_.size() && text_[at_] != '\n' && blank(text_[at_])) ++at_;
  std::size_t end = at_;
  while (end < text_.size() && text_[end] != '\n') ++end;
  std::string_view r = text_.substr(at_, end - at_);
  at_ = end;
  while (!r.empty() && blank(r.back())) r.remove_suffix(1);
  return r;
}

void TextReader::fail(const std::string& what) const {
  throw InputError(source_ + ":" + std::to_string(line_) + ": " + (context_.empty() ? "" : "in " + context_ + ": ") + what);
}

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the file");
  return std::move(s).str();
}

}  // namespace anisocert::io
