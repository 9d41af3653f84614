#include "fuzz/support/geometric_mutator.hpp"

#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace anisocert::fuzz {
namespace {

constexpr std::size_t slot_bytes = 8;

double read_slot(const std::uint8_t* data, std::size_t header, std::size_t k) {
  std::uint64_t bits = 0;
  for (std::size_t b = 0; b < slot_bytes; ++b) bits |= std::uint64_t{data[header + k * slot_bytes + b]} << (8 * b);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

double special_value(std::minstd_rand& rng) {
  static const std::array<double, 18> values{0.0,
                                             -0.0,
                                             1.0,
                                             -1.0,
                                             0.5,
                                             2.0,
                                             DBL_MAX,
                                             -DBL_MAX,
                                             DBL_MIN,
                                             -DBL_MIN,
                                             std::numeric_limits<double>::denorm_min(),
                                             -std::numeric_limits<double>::denorm_min(),
                                             std::numeric_limits<double>::infinity(),
                                             -std::numeric_limits<double>::infinity(),
                                             std::numeric_limits<double>::quiet_NaN(),
                                             0.1,
                                             1e-300,
                                             1e300};
  return values[rng() % values.size()];
}

double a_few_ulps_from(double v, std::minstd_rand& rng) {
  const int k = 1 + static_cast<int>(rng() % 4);
  const double towards = rng() % 2 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < k; ++i) v = std::nextafter(v, towards);
  return v;
}

}  // namespace

std::vector<double> slots_of(const std::uint8_t* data, std::size_t size, std::size_t header) {
  std::vector<double> v;
  for (std::size_t k = 0; size >= header && k < (size - header) / slot_bytes; ++k) v.push_back(read_slot(data, header, k));
  return v;
}

void write_slot(std::uint8_t* data, std::size_t header, std::size_t k, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof v);
  for (std::size_t b = 0; b < slot_bytes; ++b) data[header + k * slot_bytes + b] = static_cast<std::uint8_t>(bits >> (8 * b));
}

std::size_t mutate_geometry(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed,
                            std::size_t header, ByteMutator fallback) {
  std::minstd_rand rng(seed);
  // Room for one more slot: grow by one, as an engine's insertion would.
  if (size >= header && size + slot_bytes <= max_size && rng() % 8 == 0) {
    std::memset(data + size, 0, slot_bytes);
    size = header + ((size - header) / slot_bytes + 1) * slot_bytes;
  }
  if (size < header + slot_bytes || rng() % 2 == 0) return fallback(data, size, max_size);
  const std::size_t n = (size - header) / slot_bytes;
  const auto any = [&] { return static_cast<std::size_t>(rng() % n); };
  const std::size_t k = any();
  const std::size_t points = n / 2;
  const auto point = [&](std::size_t p) { return std::array<double, 2>{read_slot(data, header, 2 * p), read_slot(data, header, 2 * p + 1)}; };
  const auto set_point = [&](std::size_t p, std::array<double, 2> v) {
    write_slot(data, header, 2 * p, v[0]);
    write_slot(data, header, 2 * p + 1, v[1]);
  };
  switch (rng() % 7) {
    case 0:
      write_slot(data, header, k, special_value(rng));
      break;
    case 1:
      write_slot(data, header, k, read_slot(data, header, any()));
      break;
    case 2:
      write_slot(data, header, k, a_few_ulps_from(read_slot(data, header, any()), rng));
      break;
    case 3:
      write_slot(data, header, k, static_cast<double>(static_cast<int>(rng() % 17) - 8) / (1 << (rng() % 4)));
      break;
    case 4:  // a point on the (Euclidean) bisector of two others
      if (points >= 3) {
        const auto a = point(rng() % points), b = point(rng() % points);
        const double t = static_cast<double>(static_cast<int>(rng() % 5) - 2) / 2;
        set_point(rng() % points, {(a[0] + b[0]) / 2 - t * (b[1] - a[1]), (a[1] + b[1]) / 2 + t * (b[0] - a[0])});
      }
      break;
    case 5:  // four cocircular points: a mirrored across the bisector of b and c
      if (points >= 4) {
        const auto a = point(rng() % points), b = point(rng() % points), c = point(rng() % points);
        const double dx = c[0] - b[0], dy = c[1] - b[1], d2 = dx * dx + dy * dy;
        if (d2 > 0 && std::isfinite(d2)) {
          const double s = 2 * ((a[0] - (b[0] + c[0]) / 2) * dx + (a[1] - (b[1] + c[1]) / 2) * dy) / d2;
          set_point(rng() % points, {a[0] - s * dx, a[1] - s * dy});
        }
      }
      break;
    default:  // the midpoint of two slots
      write_slot(data, header, k, (read_slot(data, header, any()) + read_slot(data, header, any())) / 2);
      break;
  }
  return size;
}

}  // namespace anisocert::fuzz
