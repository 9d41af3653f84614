#pragma once
// Reading the binary formats (Medit .meshb/.solb, Gmsh binary .msh): fixed-size integers and IEEE
// reals in the file's byte order, each real read as the rational it is (NaN and infinities are
// refused), every failure an InputError "source: byte N: in CONTEXT: what".
#include "io/input_error.hpp"
#include "numbers/rational.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

namespace anisocert::io {

class BinaryReader {
 public:
  BinaryReader(std::string_view bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

  void set_swapped(bool swapped) { swapped_ = swapped; }   // the file's byte order is not the machine's
  std::size_t offset() const { return at_; }
  std::size_t size() const { return bytes_.size(); }
  bool at_end() const { return at_ >= bytes_.size(); }
  void seek(std::size_t offset, std::string_view what);
  void skip(std::uint64_t n, std::string_view what);

  std::int32_t int32(std::string_view what) { return load<std::int32_t>(what); }
  std::int64_t int64(std::string_view what) { return load<std::int64_t>(what); }
  std::uint64_t uint64(std::string_view what) { return load<std::uint64_t>(what); }
  double real32(std::string_view what) { return std::bit_cast<float>(load<std::uint32_t>(what)); }
  double real64(std::string_view what) { return std::bit_cast<double>(load<std::uint64_t>(what)); }
  // A real of the given width (4 or 8 bytes) as the exact rational it is.
  Rational real(int width, std::string_view what);
  // A raw byte sequence of length n (e.g. a text section inside a binary file).
  std::string_view bytes(std::size_t n, std::string_view what);

  void set_context(std::string context) { context_ = std::move(context); }  // as TextReader's
  [[noreturn]] void fail(const std::string& what) const;        // at the current offset
  [[noreturn]] void fail_at(std::size_t offset, const std::string& what) const;

 private:
  template <class U>
  U load(std::string_view what) {
    if (bytes_.size() - at_ < sizeof(U) || at_ > bytes_.size())
      fail("the file ends inside " + std::string(what) + " (" + std::to_string(sizeof(U)) + " bytes needed)");
    U v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(U));
    at_ += sizeof(U);
    if (swapped_) {
      unsigned char b[sizeof(U)];
      std::memcpy(b, &v, sizeof(U));
      for (std::size_t i = 0; i < sizeof(U) / 2; ++i) std::swap(b[i], b[sizeof(U) - 1 - i]);
      std::memcpy(&v, b, sizeof(U));
    }
    return v;
  }
  std::string_view bytes_;
  std::string source_, context_;
  std::size_t at_ = 0;
  bool swapped_ = false;
};

}  // namespace anisocert::io
