#pragma once
// The structure-aware mutator of the differential harnesses (docs/fuzzing.md § Mutator). Their
// inputs are a header of `header` bytes, then 8-byte slots, each a little-endian double (a
// coordinate or a metric entry; consecutive slots pair up as points). Byte-level mutation rarely
// makes the inputs that break geometry; this one writes them into the slots:
//   - the values that break arithmetic: ±0, ±1, ±DBL_MAX, ±DBL_MIN, subnormals, ±Inf, NaN;
//   - exact ties: a copy of another slot, a point on the bisector of two others, the mirror image
//     of a point across the bisector of two more (four cocircular points), a midpoint;
//   - near ties: a copy a few ulps away;
//   - small integers and dyadic fractions (inputs whose arithmetic is exact in doubles).
// Half of the time it leaves the bytes to the engine's own mutator (`fallback`).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace anisocert::fuzz {

using ByteMutator = std::size_t (*)(std::uint8_t* data, std::size_t size, std::size_t max_size);

std::size_t mutate_geometry(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed,
                            std::size_t header, ByteMutator fallback);

// The slots of an input as doubles (a last partial slot is ignored), and back.
std::vector<double> slots_of(const std::uint8_t* data, std::size_t size, std::size_t header);
void write_slot(std::uint8_t* data, std::size_t header, std::size_t k, double v);

}  // namespace anisocert::fuzz

// Defines libFuzzer's custom mutator for a harness whose inputs have `header` bytes before the
// slots (only in the engine build: the replay driver runs inputs, it does not mutate them).
#if defined(ANISOCERT_FUZZ_ENGINE_BUILD)
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);
#define ANISOCERT_GEOMETRIC_MUTATOR(header)                                                                   \
  extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size, \
                                                 unsigned int seed) {                                        \
    return anisocert::fuzz::mutate_geometry(data, size, max_size, seed, header, LLVMFuzzerMutate);           \
  }
#else
#define ANISOCERT_GEOMETRIC_MUTATOR(header)
#endif
