// The two readers every format reads through (io/formats/text_reader.hpp, binary_reader.hpp): tokens
// regardless of lines, comments, exact numbers, ranges, the line reported at the end of a file,
// bytes shown escaped, reals in either byte order as the rationals they are, offsets in messages.
#include "io/formats/binary_reader.hpp"
#include "io/formats/text_reader.hpp"

#include "format_test_support.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>

namespace {

using anisocert::parse_rational;
using anisocert::Rational;
using anisocert::test_support::error_of;
using namespace anisocert::io;

TEST(TextReader, TokensAcrossLinesCommentsAndExactNumbers) {
  TextReader r("Vertices # a comment 99\n\n 2\t0.1\n-3/4 1e-3\n", "t.mesh", '#');
  r.expect("Vertices");
  EXPECT_EQ(r.integer("count", 0, 10), 2);
  EXPECT_EQ(r.line(), 3);
  EXPECT_EQ(r.number("x"), Rational(1, 10));  // the decimal, not the double nearest to it
  EXPECT_EQ(r.number("y"), Rational(-3, 4));
  EXPECT_EQ(r.number("z"), Rational(1, 1000));
  EXPECT_TRUE(r.at_end());
}

TEST(TextReader, MessagesNameTheFileTheLineTheContextAndWhat) {
  EXPECT_EQ(error_of([] {
              TextReader r("1\n2\n", "f.node");
              r.set_context("Vertices");
              r.integer("a", 0, 9), r.integer("b", 0, 9), r.integer("c", 0, 9);
            }),
            "f.node:2: in Vertices: the file ends where c was expected");  // the last token's line, not 3
  EXPECT_EQ(error_of([] { TextReader("12", "f").integer("n", 0, 9); }), "f:1: n is 12, outside [0, 9]");
  EXPECT_EQ(error_of([] { TextReader("99999999999999999999", "f").integer("n", 0, 9); }),
            "f:1: n: 99999999999999999999 is out of range");
  EXPECT_NE(error_of([] { TextReader("nan", "f").number("x"); }).find("f:1: x: \"nan\" is not an exact number"),
            std::string::npos);
  // 1e400 is exact but far past the doubles: refused by name rather than certified for minutes.
  EXPECT_NE(error_of([] { TextReader("1e400", "f").number("x"); }).find("f:1: x: \"1e400\" is outside the magnitudes"),
            std::string::npos);
  EXPECT_EQ(TextReader("1e300", "f").number("x"), parse_rational("1e300"));
  EXPECT_EQ(TextReader("1e-300", "f").number("x"), parse_rational("1e-300"));
  // A binary byte in a text file is shown escaped, never printed raw.
  EXPECT_EQ(error_of([] { TextReader(std::string_view("\x01\x02z", 3), "f").expect("MeshVersionFormatted"); }),
            "f:1: expected \"MeshVersionFormatted\", found \"\\x01\\x02z\"");
}

TEST(BinaryReader, EitherByteOrderAndExactReals) {
  const double x = 0.1;  // the double: 3602879701896397/2^55
  std::string le(8, '\0'), be(8, '\0');
  std::memcpy(le.data(), &x, 8);
  for (int i = 0; i < 8; ++i) be[i] = le[7 - i];
  BinaryReader a(le, "le.bin"), b(be, "be.bin");
  b.set_swapped(true);
  const Rational exact(3602879701896397, Rational(36028797018963968));
  EXPECT_EQ(a.real(8, "x"), exact);
  EXPECT_EQ(b.real(8, "x"), exact);
  const float f = 0.5f;
  std::string four(4, '\0');
  std::memcpy(four.data(), &f, 4);
  EXPECT_EQ(BinaryReader(four, "f").real(4, "x"), Rational(1, 2));
}

TEST(BinaryReader, MessagesNameTheByte) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::string bytes(12, '\0');
  std::memcpy(bytes.data() + 4, &nan, 8);
  EXPECT_EQ(error_of([&] {
              BinaryReader r(bytes, "n.meshb");
              r.set_context("Vertices");
              r.int32("a");
              r.real(8, "x");
            }),
            "n.meshb: byte 4: in Vertices: x is NaN");
  EXPECT_EQ(error_of([] { BinaryReader("abc", "t.bin").int32("a count"); }),
            "t.bin: byte 0: the file ends inside a count (4 bytes needed)");
  EXPECT_EQ(error_of([] { BinaryReader("abcd", "t.bin").seek(9, "a position"); }),
            "t.bin: byte 0: a position points to byte 9, past the end of the file (4 bytes)");
}

}  // namespace
