#include "io/formats/binary_reader.hpp"

#include <cmath>

namespace anisocert::io {

void BinaryReader::seek(std::size_t offset, std::string_view what) {
  if (offset > bytes_.size())
    fail(std::string(what) + " points to byte " + std::to_string(offset) + ", past the end of the file (" +
         std::to_string(bytes_.size()) + " bytes)");
  at_ = offset;
}

void BinaryReader::skip(std::uint64_t n, std::string_view what) {
  if (n > bytes_.size() - at_) fail("the file ends inside " + std::string(what));
  at_ += n;
}

std::string_view BinaryReader::bytes(std::size_t n, std::string_view what) {
  const std::size_t start = at_;
  skip(n, what);
  return bytes_.substr(start, n);
}

Rational BinaryReader::real(int width, std::string_view what) {
  const std::size_t start = at_;
  const double x = width == 4 ? real32(what) : real64(what);
  if (!std::isfinite(x)) fail_at(start, std::string(what) + " is " + (std::isnan(x) ? "NaN" : "infinite"));
  return Rational(x);  // exact: GMP's mpq_set_d
}

void BinaryReader::fail(const std::string& what) const { fail_at(at_, what); }

void BinaryReader::fail_at(std::size_t offset, const std::string& what) const {
  throw InputError(source_ + ": byte " + std::to_string(offset) + ": " + (context_.empty() ? "" : "in " + context_ + ": ") + what);
}

}  // namespace anisocert::io
