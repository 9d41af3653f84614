// The VTU reader (io/formats/vtu.hpp) on one small tetrahedral mesh written here in every encoding
// VTK's XML format allows: the bytes are made by this test's own encoder (base64 by RFC 4648's
// alphabet, zlib's compress(), the header layouts of VTK's "VTK File Formats" XML section and
// Kitware's wiki "VTK XML Formats"), never by the project's writer, and each file must read as the
// ASCII one does, exactly. The values are dyadic, so Float64 and text denote the same rationals.
#include "format_test_support.hpp"
#include "io/formats/registry.hpp"
#include "io/formats/vtu.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

namespace {

using anisocert::Rational;
using anisocert::io::MeshFile;
using anisocert::io::read_vtu;
using anisocert::test_support::error_of;

// Two tetrahedra on the face 1 2 3, and a metric per vertex (xx yy zz xy yz xz, VTK's order).
const std::vector<double> xyz{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.75, 0.5, 0.25};
const std::vector<std::int64_t> connectivity{0, 1, 2, 3, 1, 2, 3, 4}, offsets{4, 8};
const std::vector<std::int64_t> types{10, 10};
const std::vector<double> metric{4, 4, 4, 0, 0, 0,  1, 2, 3, 0.5, 0.25, 0.125,  1, 1, 1, 0, 0, 0,  16, 16, 16, 0, 0, 0,  2, 3, 4, -0.5, 0, 0.5};

template <class T>
std::string bytes_of(const std::vector<T>& v, bool big_endian) {
  std::string s;
  for (const T& x : v) {
    char b[sizeof(T)];
    std::memcpy(b, &x, sizeof(T));
    if (big_endian) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
  }
  return s;
}

std::string base64(const std::string& s) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < s.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, s.size() - i);
    std::uint32_t w = 0;
    for (std::size_t k = 0; k < 3; ++k) w = (w << 8) | (k < n ? static_cast<unsigned char>(s[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? alphabet[(w >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

struct Encoding {
  std::string name;
  std::string format = "binary";  // ascii, binary, appended
  bool zlib = false, two_streams = false, uint64_header = false, big_endian = false, appended_base64 = false, float32 = false;
  std::size_t block = 32;           // the uncompressed block size (several blocks per array)
};

std::string header_int(std::uint64_t x, const Encoding& e) {
  return e.uint64_header ? bytes_of(std::vector<std::uint64_t>{x}, e.big_endian)
                         : bytes_of(std::vector<std::uint32_t>{static_cast<std::uint32_t>(x)}, e.big_endian);
}

// The header and the data of one array, as VTK lays them out.
std::pair<std::string, std::string> laid_out(const std::string& data, const Encoding& e) {
  if (!e.zlib) return {header_int(data.size(), e), data};
  std::vector<std::string> blocks;
  for (std::size_t i = 0; i < data.size(); i += e.block) {
    const std::string plain = data.substr(i, e.block);
    uLongf n = compressBound(static_cast<uLong>(plain.size()));
    std::string z(n, '\0');
    EXPECT_EQ(compress(reinterpret_cast<Bytef*>(z.data()), &n, reinterpret_cast<const Bytef*>(plain.data()), static_cast<uLong>(plain.size())), Z_OK);
    blocks.push_back(z.substr(0, n));
  }
  std::string header = header_int(blocks.size(), e) + header_int(e.block, e) + header_int(data.size() % e.block, e), body;
  for (const auto& b : blocks) header += header_int(b.size(), e), body += b;
  return {header, body};
}

struct Array {
  std::string attributes, ascii, data;
};

std::string vtu(const Encoding& e) {
  const auto reals = [&](const std::vector<double>& v) {
    if (!e.float32) return bytes_of(v, e.big_endian);
    std::vector<float> f(v.begin(), v.end());
    return bytes_of(f, e.big_endian);
  };
  const auto text = [](const auto& v) {
    std::ostringstream o;
    for (const auto& x : v) o << x << ' ';
    return o.str();
  };
  const std::string real_type = e.float32 ? "Float32" : "Float64";
  std::vector<std::int32_t> c32(connectivity.begin(), connectivity.end());
  std::vector<std::uint8_t> t8(types.begin(), types.end());
  const std::vector<std::pair<std::string, Array>> arrays{
      {"Points", {"type=\"" + real_type + "\" NumberOfComponents=\"3\"", text(xyz), reals(xyz)}},
      {"Cells", {"type=\"Int32\" Name=\"connectivity\"", text(connectivity), bytes_of(c32, e.big_endian)}},
      {"Cells", {"type=\"Int64\" Name=\"offsets\"", text(offsets), bytes_of(offsets, e.big_endian)}},
      {"Cells", {"type=\"UInt8\" Name=\"types\"", text(types), bytes_of(t8, e.big_endian)}},
      {"PointData", {"type=\"" + real_type + "\" Name=\"Metric\" NumberOfComponents=\"6\"", text(metric), reals(metric)}}};
  std::string body, appended;
  std::string section;
  for (const auto& [parent, a] : arrays) {
    if (parent != section) {
      if (!section.empty()) body += "</" + section + ">\n";
      body += "<" + parent + ">\n";
      section = parent;
    }
    if (e.format == "ascii") {
      body += "<DataArray " + a.attributes + " format=\"ascii\">\n" + a.ascii + "\n</DataArray>\n";
      continue;
    }
    const auto [header, data] = laid_out(a.data, e);
    if (e.format == "binary") {
      const std::string encoded = e.two_streams ? base64(header) + base64(data) : base64(header + data);
      body += "<DataArray " + a.attributes + " format=\"binary\">\n  " + encoded + "\n</DataArray>\n";
    } else {
      body += "<DataArray " + a.attributes + " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
      appended += e.appended_base64 ? base64(header) + base64(data) : header + data;
    }
  }
  body += "</" + section + ">\n";
  std::string file = "<?xml version=\"1.0\"?>\n<!-- written by vtu_test.cpp -->\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" +
                     std::string(e.big_endian ? "BigEndian" : "LittleEndian") + "\"" + (e.uint64_header ? " header_type=\"UInt64\"" : "") +
                     (e.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">\n" +
                     body + "</Piece>\n</UnstructuredGrid>\n";
  if (e.format == "appended")
    file += "<AppendedData encoding=\"" + std::string(e.appended_base64 ? "base64" : "raw") + "\">\n   _" + appended + "\n</AppendedData>\n";
  return file + "</VTKFile>\n";
}

void expect_same(const MeshFile& a, const MeshFile& b, const std::string& name) {
  ASSERT_EQ(a.dimension, 3) << name;
  ASSERT_EQ(b.dimension, 3) << name;
  ASSERT_EQ(a.mesh3.vertices.size(), b.mesh3.vertices.size()) << name;
  for (std::size_t i = 0; i < a.mesh3.vertices.size(); ++i) {
    const auto &p = a.mesh3.vertices[i], &q = b.mesh3.vertices[i];
    EXPECT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z) << name << ": vertex " << i;
  }
  EXPECT_EQ(a.mesh3.tetrahedra, b.mesh3.tetrahedra) << name;
  EXPECT_EQ(a.mesh3.metrics, b.mesh3.metrics) << name;
}

TEST(Vtu, EveryEncodingReadsAsTheAsciiFile) {
  const MeshFile ascii = read_vtu(vtu({.name = "ascii", .format = "ascii"}), "ascii.vtu");
  ASSERT_EQ(ascii.mesh3.vertices.size(), 5u);
  EXPECT_EQ(ascii.mesh3.vertices[4].x, Rational(3, 4));
  EXPECT_EQ(ascii.mesh3.tetrahedra, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  // Vertex 1's metric [1 0.5 0.125; 0.5 2 0.25; 0.125 0.25 3] from xx yy zz xy yz xz = 1 2 3 0.5 0.25 0.125.
  const auto& M = ascii.mesh3.metrics[1];
  EXPECT_EQ(M, (anisocert::predicates::Sym3<Rational>{1, Rational(1, 2), Rational(1, 8), 2, Rational(1, 4), 3}));
  for (const Encoding& e : {Encoding{.name = "binary, one stream"}, Encoding{.name = "binary, two streams", .two_streams = true},
                            Encoding{.name = "binary, zlib", .zlib = true, .two_streams = true},
                            Encoding{.name = "binary, zlib, one stream", .zlib = true},
                            Encoding{.name = "binary, zlib, one block", .zlib = true, .two_streams = true, .block = 1 << 15},
                            Encoding{.name = "binary, UInt64 header", .uint64_header = true},
                            Encoding{.name = "binary, big endian, zlib", .zlib = true, .two_streams = true, .big_endian = true},
                            Encoding{.name = "binary, Float32", .float32 = true},
                            Encoding{.name = "appended raw", .format = "appended"},
                            Encoding{.name = "appended raw, zlib, UInt64", .format = "appended", .zlib = true, .uint64_header = true},
                            Encoding{.name = "appended base64", .format = "appended", .appended_base64 = true},
                            Encoding{.name = "appended base64, zlib", .format = "appended", .zlib = true, .appended_base64 = true}}) {
    const std::string text = vtu(e);
    try {
      expect_same(ascii, read_vtu(text, e.name + ".vtu"), e.name);
    } catch (const std::exception& x) {
      ADD_FAILURE() << e.name << ": " << x.what();
    }
  }
}

TEST(Vtu, TheWriterReadsBackExactly) {
  MeshFile m = read_vtu(vtu({.name = "ascii", .format = "ascii"}), "ascii.vtu");
  m.mesh3.vertices[4].x = Rational(1, 10);  // a decimal no double is
  m.mesh3.triangles = {{1, 2, 3}};
  const MeshFile back = read_vtu(anisocert::io::vtu_text(m), "back.vtu");
  expect_same(m, back, "written");
  EXPECT_EQ(back.mesh3.triangles, m.mesh3.triangles);
  m.mesh3.vertices[4].x = Rational(1, 3);
  EXPECT_NE(error_of([&] { anisocert::io::vtu_text(m); }).find("point 4 x"), std::string::npos);
}

TEST(Vtu, ATriangleMeshIsPlanarWithItsOwnMetricOrders) {
  const std::string head = "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"3\" NumberOfCells=\"1\"><Points>"
                           "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points><Cells>"
                           "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
                           "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray>"
                           "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5</DataArray></Cells>";
  const auto with = [&](int comps, const std::string& values) {
    return head + "<PointData><DataArray type=\"Float64\" Name=\"metric\" NumberOfComponents=\"" + std::to_string(comps) + "\" format=\"ascii\">" +
           values + "</DataArray></PointData></Piece></UnstructuredGrid></VTKFile>";
  };
  // Omega_h's 2D order is xx yy xy: 4 9 1 is [4 1; 1 9].
  const MeshFile three = read_vtu(with(3, "4 9 1 4 9 1 4 9 1"), "t.vtu");
  ASSERT_EQ(three.dimension, 2);
  EXPECT_EQ(three.mesh.metrics[0], (anisocert::predicates::Sym2<Rational>{4, 1, 9}));
  const MeshFile four = read_vtu(with(4, "4 1 1 9 4 1 1 9 4 1 1 9"), "f.vtu");
  EXPECT_EQ(four.mesh.metrics, three.mesh.metrics);
  const MeshFile size = read_vtu(with(1, "0.5 0.5 0.5"), "s.vtu");
  EXPECT_EQ(size.mesh.metrics[0].m11, 4);  // I / h², h = 1/2
  EXPECT_NE(error_of([&] { read_vtu(with(4, "4 1 2 9 4 1 1 9 4 1 1 9"), "a.vtu"); }).find("the metric of point 0 is not symmetric"), std::string::npos);
  EXPECT_NE(error_of([&] { read_vtu(with(3, "1 1 2 4 9 1 4 9 1"), "p.vtu"); }).find("the metric of point 0 is not positive definite"), std::string::npos);
  std::string lifted = with(1, "1 1 1");
  lifted.replace(lifted.find("0 1 0<"), 6, "0 1 1<");
  EXPECT_NE(error_of([&] { read_vtu(lifted, "z.vtu"); }).find("z.vtu:1: in <DataArray> of <Points>: point 2 has z = 1 and there is no tetrahedron"),
            std::string::npos);
}

TEST(Vtu, BadFilesAreNamedByLineOrByte) {
  const std::string good = vtu({.name = "zlib", .zlib = true, .two_streams = true});
  const auto broken = [&](std::string from, std::string to, std::string text) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  const auto message = [](const std::string& text) { return error_of([&] { read_vtu(text, "bad.vtu"); }); };
  EXPECT_NE(message(broken("10 10 ", "10 12 ", vtu({.name = "ascii", .format = "ascii"}))).find("cell 1 is a hexahedron (type 12)"), std::string::npos);
  EXPECT_NE(message(broken("1 2 3 4 ", "1 2 3 5 ", vtu({.name = "ascii", .format = "ascii"}))).find("entry 7 is vertex 5, not one of the 5 points"), std::string::npos);
  EXPECT_NE(message(broken("4 8 ", "4 9 ", vtu({.name = "ascii", .format = "ascii"}))).find("cell 1 ends at 9, not 8"), std::string::npos);
  EXPECT_NE(message(broken("UnstructuredGrid\" version", "PolyData\" version", good)).find("anisocert reads UnstructuredGrid"), std::string::npos);
  const auto line_of = [&](const std::string& what) { return std::to_string(1 + std::count(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.find(what)), '\n')); };
  EXPECT_NE(message(broken("<Piece", "<Part", good)).find("bad.vtu:" + line_of("</Piece>") + ": </Piece> closes <Part>"), std::string::npos);
  EXPECT_NE(message(broken("</Piece>", "</Part>", broken("<Piece", "<Part", good))).find("there is no <Piece>"), std::string::npos);
  // A base64 stream cut short, and a compressed block whose bytes are not zlib's.
  const std::size_t data = good.find("format=\"binary\">") + 20;
  EXPECT_NE(message(good.substr(0, data + 40) + good.substr(good.find("</DataArray>", data))).find("bad.vtu:" + line_of("<DataArray") + ": in <DataArray> of <Points>: the data ends"),
            std::string::npos);
  std::string garbled = good;
  char& c = garbled[good.find("</DataArray>", data) - 12];
  c = c == 'A' ? 'B' : 'A';
  EXPECT_NE(message(garbled).find("does not inflate"), std::string::npos);
  // A raw appended array claiming more bytes than the file has: named by byte.
  const std::string raw = vtu({.name = "raw", .format = "appended"});
  std::string claimed = raw;
  const std::size_t underscore = raw.find('_', raw.find("<AppendedData"));
  claimed.replace(underscore + 1, 4, std::string("\xff\xff\xff\x00", 4));
  EXPECT_NE(message(claimed).find("the header counts 16777215 bytes"), std::string::npos);
  EXPECT_NE(message(broken("Float64\" NumberOfComponents=\"3\"", "Float64\" NumberOfComponents=\"2\"", good)).find("NumberOfComponents is \"2\", not 3"),
            std::string::npos);
}

// A reviewer's findings: VTK writes <InformationKey> elements inside a DataArray after its values;
// a DataArray without a format is ASCII; counts far beyond the data are refused by name, not by
// an allocation of their size.
TEST(Vtu, InformationKeysDefaultFormatAndImpossibleCounts) {
  std::string text = vtu({.name = "ascii", .format = "ascii"});
  const std::size_t first = text.find("\n</DataArray>");
  text.insert(first, "\n<InformationKey name=\"L2_NORM_RANGE\" location=\"vtkDataArray\" length=\"2\"><Value index=\"0\">0</Value></InformationKey>");
  const std::size_t format = text.find(" format=\"ascii\"", text.find("Name=\"offsets\""));
  text.erase(format, std::string(" format=\"ascii\"").size());
  const MeshFile f = read_vtu(text, "keys.vtu");
  EXPECT_EQ(f.mesh3.vertices.size(), 5u);
  EXPECT_EQ(f.mesh3.tetrahedra.size(), 2u);
  std::string huge = vtu({.name = "ascii", .format = "ascii"});
  huge.replace(huge.find("NumberOfPoints=\"5\""), 18, "NumberOfPoints=\"2147483647\"");
  EXPECT_NE(error_of([&] { read_vtu(huge, "huge.vtu"); }).find("is missing"), std::string::npos);
  std::string huge_binary = vtu({.name = "binary", .two_streams = true});
  huge_binary.replace(huge_binary.find("NumberOfPoints=\"5\""), 18, "NumberOfPoints=\"2147483647\"");
  EXPECT_NE(error_of([&] { read_vtu(huge_binary, "huge.vtu"); }).find("the file is too short"), std::string::npos);
}

TEST(Vtu, TheRegistryReadsAndWritesVtuByExtension) {
  const auto dir = anisocert::test_support::fresh_dir("vtu_registry");
  std::ofstream(dir / "m.vtu") << vtu({.name = "zlib", .zlib = true, .two_streams = true});
  const MeshFile f = anisocert::io::read_mesh_file((dir / "m.vtu").string());
  EXPECT_EQ(f.dimension, 3);
  EXPECT_EQ(f.metric_source, (dir / "m.vtu").string());
  EXPECT_EQ(anisocert::io::mesh_format_to_write("x.vtu").name, "vtu");
}

}  // namespace
