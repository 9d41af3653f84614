#pragma once
// The bytes of a fuzz input read one at a time by the harnesses that decode small integers from
// them (refiners_certified, certify_simple, conics_second_engine): past the end every byte is 0,
// so a short input is a valid input with defaults.
#include <cstddef>
#include <cstdint>

namespace anisocert::fuzz {

class ByteSource {
 public:
  ByteSource(const std::uint8_t* data, std::size_t size, std::size_t start = 0) : data_(data), size_(size), at_(start) {}
  bool exhausted() const { return at_ >= size_; }
  unsigned next() { return at_ < size_ ? data_[at_++] : 0u; }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_;
};

}  // namespace anisocert::fuzz
