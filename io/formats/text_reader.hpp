#pragma once
// Reading the text formats (Medit ASCII, Gmsh ASCII, Triangle, FreeFem/BAMG) by token: a token is
// a run of non-blank characters, so a keyword and its value may sit on one line or on two (MMG
// writes both). Every number is read as the rational its text denotes (0.1 is 1/10), and every
// failure is an InputError "source:LINE: in CONTEXT: what" naming the file, the line (at the end of
// the file: the line of the last token), the section being read and what was expected.
#include "io/input_error.hpp"
#include "numbers/rational.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace anisocert::io {

class TextReader {
 public:
  // comment: a character that starts a comment running to the end of its line ('#' for Medit
  // and Triangle), or '\0' for none.
  TextReader(std::string_view text, std::string source, char comment = '\0');

  bool at_end();                       // only blanks and comments remain
  std::string_view token(std::string_view what);   // the next token; fails at the end with "what"
  std::string_view peek();             // the next token without consuming it ("" at the end)
  void expect(std::string_view keyword);
  std::int64_t integer(std::string_view what, std::int64_t lo, std::int64_t hi);
  // Exact, within the magnitudes anisocert reads (parse_input_number; else refused, named).
  Rational number(std::string_view what);
  std::string_view rest_of_line();     // the remainder of the current line, blanks trimmed
  int line() const { return line_; }
  const std::string& source() const { return source_; }
  void set_context(std::string context) { context_ = std::move(context); }  // "Vertices", "$Nodes"; "" for none
  [[noreturn]] void fail(const std::string& what) const;  // "source:LINE: in CONTEXT: what"

 private:
  void skip_blanks();
  std::string_view text_;
  std::size_t at_ = 0;
  int line_ = 1, token_line_ = 1;
  std::string source_, context_;
  char comment_;
};

// The whole file at path (an InputError naming it when it cannot be read).
std::string read_whole_file(const std::string& path);

}  // namespace anisocert::io
