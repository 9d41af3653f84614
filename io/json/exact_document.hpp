#pragma once
// A JSON document read so that every number stays exact (DESIGN.md § Numbers: "numbers are read
// as the rationals their text denotes"): a number with a fraction or an exponent, or too large for
// 64 bits, is kept as its text (a JSON string, which parse_rational then reads exactly: the JSON
// number 0.1 becomes "0.1"); integers that fit in 64 bits stay JSON integers, which are exact.
// A key repeated within one object is an error instead of silently keeping the last value.
#include "io/input_error.hpp"

#include <nlohmann/json.hpp>

#include <istream>
#include <string>

namespace anisocert::io {

// Throws InputError naming `source` and the byte position of malformed JSON, or the path of a
// repeated key.
nlohmann::json parse_exact_json(std::istream& in, const std::string& source);

}  // namespace anisocert::io
