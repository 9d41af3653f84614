#pragma once
// DESIGN.md § Command line: bad input is one short line naming what is wrong and where. A reader's
// InputError is the expected answer to a bad file; its message must keep that contract.
#include "fuzz/support/finding.hpp"

#include <string_view>

namespace anisocert::fuzz {

// The longest message a bad input may produce: a source path, a place and a bounded excerpt.
inline constexpr std::size_t max_message_length = 1024;

// source: a part of the file name every message of this input must contain.
inline void require_one_short_line(std::string_view message, std::string_view source) {
  require(!message.empty(), "an empty error message");
  require(message.find_first_of("\n\r") == std::string_view::npos,
          "an error message of more than one line: " + std::string(message.substr(0, 200)));
  require(message.size() <= max_message_length,
          "an error message of " + std::to_string(message.size()) + " bytes: " + std::string(message.substr(0, 200)));
  require(source.empty() || message.find(source) != std::string_view::npos,
          "an error message that does not name its file (" + std::string(source) + "): " + std::string(message.substr(0, 200)));
}

}  // namespace anisocert::fuzz
