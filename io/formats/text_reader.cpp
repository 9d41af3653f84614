#include "io/formats/text_reader.hpp"

#include "io/input_file.hpp"
#include "numbers/excerpt.hpp"

#include <fstream>
#include <sstream>

namespace anisocert::io {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

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
  if (t != keyword) fail("expected \"" + std::string(keyword) + "\", found " + quoted_excerpt(t));
}

std::int64_t TextReader::integer(std::string_view what, std::int64_t lo, std::int64_t hi) {
  const std::string_view t = token(what);
  std::size_t i = 0;
  bool negative = false;
  if (t[0] == '+' || t[0] == '-') negative = t[0] == '-', i = 1;
  if (i == t.size()) fail(std::string(what) + ": " + quoted_excerpt(t) + " is not an integer");
  std::int64_t v = 0;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (c < '0' || c > '9') fail(std::string(what) + ": " + quoted_excerpt(t) + " is not an integer");
    if (v > (INT64_MAX - (c - '0')) / 10) fail(std::string(what) + ": " + excerpt(t) + " is out of range");
    v = v * 10 + (c - '0');
  }
  if (negative) v = -v;
  if (v < lo || v > hi)
    fail(std::string(what) + " is " + excerpt(t) + ", outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

Rational TextReader::number(std::string_view what) {
  const std::string_view t = token(what);
  try {
    return parse_input_number(t);  // exact, within the magnitudes anisocert reads
  } catch (const NumberSyntaxError& e) {  // e names the text as an excerpt
    fail(std::string(what) + ": " + e.what());
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
  std::ifstream in = open_input(path);
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the file");
  return std::move(s).str();
}

}  // namespace anisocert::io
