// The oracle's exact conic intersection against the second engine (docs/fuzzing.md § Differential):
// FLINT's resultants and Calcium's qqbar (property_tests/second_engine/, no code shared with
// oracle/). Small integer coefficients, decoded from bytes; the first byte picks a construction
// that reaches the degenerate cases bytes alone rarely hit (property_tests/generators/conic_pairs.hpp,
// the constructions of the property Oracle.ConicIntersectionAgreesWithQqbar):
//   0 two conics from their coefficients;
//   1 two members of the pencil through four points (four common points, some possibly equal);
//   2 a conic through a point and one tangent to it there (a double point);
//   3 two line pairs sharing a line (a shared component);
//   4 two line pairs through one point (a point singular for both).
// Both engines must give the same shared-component verdict, the same real points (each qqbar point
// a root of our defining polynomial inside our isolating interval), the same multiplicities and
// the same order in x and y. Limit: 32 bytes.
#include "fuzz/support/byte_source.hpp"
#include "fuzz/support/finding.hpp"
#include "oracle/algebraic/conic_intersection.hpp"
#include "property_tests/generators/conic_pairs.hpp"
#include "property_tests/second_engine/qqbar_conics.hpp"

using anisocert::Rational;
using anisocert::fuzz::require;
using anisocert::oracle::Conic;
namespace qq = anisocert::second_engine;
namespace gen = anisocert::gen;

namespace {

// Small integers in [−6, 6] from the bytes; 0 past the end.
struct SmallIntegers {
  anisocert::fuzz::ByteSource bytes;
  Rational small() { return bytes.exhausted() ? Rational(0) : Rational(static_cast<int>(bytes.next() % 13) - 6); }
  Conic conic() {
    Conic c;
    for (Rational* k : {&c.a, &c.b, &c.c, &c.d, &c.e, &c.f}) *k = small();
    return c;
  }
  gen::RPoint point() {
    Rational x = small();
    return {x, small()};
  }
};

gen::ConicPair decode(SmallIntegers& b, int kind) {
  switch (kind) {
    case 1: {
      const auto p1 = b.point(), p2 = b.point(), p3 = b.point(), p4 = b.point();
      const Rational l = b.small(), m = b.small();
      return gen::through_four_points(p1, p2, p3, p4, l, m);
    }
    case 2: {
      const Conic A = b.conic();
      const auto p = b.point();
      return gen::tangent_at(A, p, b.small());
    }
    case 3: {
      const auto p = b.point(), q = b.point(), r = b.point(), s = b.point(), t = b.point();
      return gen::sharing_a_line(p, q, r, s, t);
    }
    case 4: {
      const auto o = b.point(), p = b.point(), q = b.point(), r = b.point(), s = b.point();
      return gen::singular_at(o, p, q, r, s);
    }
    default: {
      const Conic A = b.conic();
      return {A, b.conic()};
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 32) return -1;
  SmallIntegers b{anisocert::fuzz::ByteSource(data, size, 1)};
  const auto [A, B] = decode(b, data[0] % 5);
  if (A.polynomial().is_zero() || B.polynomial().is_zero()) return 0;  // not conics
  const auto ours = anisocert::oracle::intersect(A, B);
  const qq::QIntersection theirs = qq::intersect(A, B);
  require(ours.shared_component == theirs.shared_component, "the two engines disagree on a shared component");
  require(ours.points.size() == theirs.points.size(), "the two engines find different numbers of common points");
  for (std::size_t k = 0; k < ours.points.size(); ++k) {
    const auto& p = ours.points[k].point;
    require(qq::equals(theirs.points[k].x, p.x()) && qq::equals(theirs.points[k].y, p.y()),
            "common point " + std::to_string(k) + " differs between the engines");
    require(ours.points[k].multiplicity == theirs.points[k].multiplicity,
            "the multiplicity of common point " + std::to_string(k) + " differs between the engines");
    for (std::size_t j = 0; j < ours.points.size(); ++j) {
      require(static_cast<int>(compare_x(p, ours.points[j].point)) == qq::compare_x(theirs.points[k], theirs.points[j]),
              "the engines order common points differently in x");
      require(static_cast<int>(compare_y(p, ours.points[j].point)) == qq::compare_y(theirs.points[k], theirs.points[j]),
              "the engines order common points differently in y");
    }
  }
  return 0;
}
