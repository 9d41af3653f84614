#include "io/formats/vtu.hpp"

#include "io/formats/text_reader.hpp"
#include "numbers/excerpt.hpp"
#include "numbers/rational.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace anisocert::io {
namespace {

using predicates::Point2;
using predicates::Point3;
using predicates::Sym2;
using predicates::Sym3;

constexpr std::int64_t vtk_triangle = 5, vtk_tetra = 10;

std::string cell_type_name(std::int64_t t) {
  switch (t) {
    case 1: return "a vertex (type 1)";
    case 3: return "a line (type 3)";
    case 9: return "a quadrilateral (type 9)";
    case 12: return "a hexahedron (type 12)";
    case 13: return "a wedge (type 13)";
    case 14: return "a pyramid (type 14)";
    case 22: return "a quadratic triangle (type 22)";
    case 24: return "a quadratic tetrahedron (type 24)";
    default: return "cell type " + std::to_string(t);
  }
}

// One element of the XML: its name, attributes and where its content lies.
struct Element {
  std::string name, parent;
  std::map<std::string, std::string> attributes;
  std::size_t begin = 0, end = 0;  // content [begin, end) in the file
  std::size_t at = 0;              // the '<' of its start tag
};

class VtuReader {
 public:
  VtuReader(std::string_view bytes, std::string source) : b_(bytes), source_(std::move(source)) {}

  MeshFile read();

 private:
  // "source:LINE: in CONTEXT: what", or "source: byte N: …" inside appended raw data.
  [[noreturn]] void fail(std::size_t at, const std::string& context, const std::string& what) const {
    const bool in_raw_data = appended_ && raw_ && at >= appended_begin_;
    const std::string where = in_raw_data ? ": byte " + std::to_string(at)
                                          : ":" + std::to_string(1 + std::count(b_.begin(), b_.begin() + static_cast<std::ptrdiff_t>(std::min(at, b_.size())), '\n'));
    throw InputError(source_ + where + ": " + (context.empty() ? "" : "in " + context + ": ") + what);
  }

  void scan();
  std::size_t tag(std::size_t at, std::vector<std::string>& open);
  const Element& only(const std::string& name) const;
  std::string attribute(const Element& e, const std::string& name, const std::string& fallback = "") const;
  std::int64_t count_attribute(const Element& e, const std::string& name, std::int64_t hi) const;

  // The values of a DataArray: count·components numbers, as rationals (reals) or integers.
  std::vector<Rational> reals(const Element& e, std::size_t count, int components);
  std::vector<std::int64_t> integers(const Element& e, std::size_t count);
  std::string payload(const Element& e, std::size_t bytes);
  // The n blank-separated values of an ASCII array, each given to take(text, offset); fewer or
  // more than n are refused.
  template <class Take>
  void ascii_values(const Element& e, std::size_t n, const std::string& context, Take&& take) {
    std::size_t i = e.begin;
    const std::size_t end = text_end(e);
    for (std::size_t k = 0; k < n; ++k) {
      while (i < end && std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
      if (i >= end) fail(i, context, "value " + std::to_string(k + 1) + " of " + std::to_string(n) + " is missing");
      const std::size_t s = i;
      while (i < end && !std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
      take(b_.substr(s, i - s), s);
    }
    while (i < end && std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
    if (i < end) fail(i, context, "more than the " + std::to_string(n) + " values the array holds");
  }
  // Where an array's own text ends: at its first child element (VTK writes <InformationKey>
  // elements after the values) or its end tag.
  std::size_t text_end(const Element& e) const { return std::min(e.end, b_.find('<', e.begin)); }
  std::string context_of(const Element& e) const {
    const std::string n = attribute(e, "Name");
    return "<DataArray" + (n.empty() ? std::string() : " Name=" + quoted_excerpt(n)) + "> of <" + excerpt(e.parent) + ">";
  }

  std::string_view b_;
  std::string source_;
  std::vector<Element> elements_;
  bool appended_ = false, raw_ = false, big_endian_ = false, compressed_ = false;
  int header_bytes_ = 4;
  std::size_t appended_begin_ = 0;  // the byte after the '_'
};

// Tags until <AppendedData>, whose content is data (raw bytes may hold '<').
void VtuReader::scan() {
  std::vector<std::string> open;
  std::size_t at = 0;
  while ((at = b_.find('<', at)) != std::string_view::npos) at = tag(at, open);
}

std::size_t VtuReader::tag(std::size_t at, std::vector<std::string>& open) {
  const auto skip_to = [&](std::string_view end, const char* what) {
    const std::size_t e = b_.find(end, at);
    if (e == std::string_view::npos) fail(at, "", std::string(what) + " is never closed");
    return e + end.size();
  };
  if (b_.substr(at, 4) == "<!--") return skip_to("-->", "a comment");
  if (b_.substr(at, 2) == "<?") return skip_to("?>", "a processing instruction");
  if (b_.substr(at, 2) == "<!") return skip_to(">", "a declaration");
  const bool closing = b_.substr(at, 2) == "</";
  std::size_t i = at + (closing ? 2 : 1);
  const std::size_t name_begin = i;
  while (i < b_.size() && (std::isalnum(static_cast<unsigned char>(b_[i])) || b_[i] == '_' || b_[i] == ':' || b_[i] == '-')) ++i;
  const std::string name(b_.substr(name_begin, i - name_begin));
  if (name.empty()) fail(at, "", "a '<' that starts no tag");
  if (closing) {
    if (open.empty() || open.back() != name)
      fail(at, "", "</" + excerpt(name) + "> closes " + (open.empty() ? std::string("nothing") : "<" + excerpt(open.back()) + ">"));
    open.pop_back();
    for (auto e = elements_.rbegin(); e != elements_.rend(); ++e)
      if (e->name == name && e->end == 0) {
        e->end = at;
        break;
      }
    return skip_to(">", "an end tag");
  }
  Element e;
  e.name = name, e.at = at, e.parent = open.empty() ? "" : open.back();
  for (;;) {
    while (i < b_.size() && std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
    if (i >= b_.size()) fail(at, "", "the tag <" + excerpt(name) + "> is never closed");
    if (b_[i] == '>' || b_.substr(i, 2) == "/>") break;
    const std::size_t key_begin = i;
    while (i < b_.size() && b_[i] != '=' && b_[i] != '>' && !std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
    const std::string key(b_.substr(key_begin, i - key_begin));
    while (i < b_.size() && std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
    if (i >= b_.size() || b_[i] != '=') fail(key_begin, "<" + excerpt(name) + ">", "the attribute " + quoted_excerpt(key) + " has no value");
    ++i;
    while (i < b_.size() && std::isspace(static_cast<unsigned char>(b_[i]))) ++i;
    if (i >= b_.size() || (b_[i] != '"' && b_[i] != '\'')) fail(key_begin, "<" + excerpt(name) + ">", "the value of " + quoted_excerpt(key) + " is not quoted");
    const std::size_t close = b_.find(b_[i], i + 1);
    if (close == std::string_view::npos) fail(key_begin, "<" + excerpt(name) + ">", "the value of " + quoted_excerpt(key) + " is never closed");
    e.attributes[key] = std::string(b_.substr(i + 1, close - i - 1));
    i = close + 1;
  }
  const bool empty = b_[i] == '/';
  e.begin = i + (empty ? 2 : 1);
  if (empty) e.end = e.begin;
  if (name == "AppendedData") {
    const std::string encoding = attribute(e, "encoding", "raw");
    if (encoding != "raw" && encoding != "base64") fail(at, "<AppendedData>", "the encoding " + quoted_excerpt(encoding) + " is neither raw nor base64");
    std::size_t u = e.begin;
    while (u < b_.size() && std::isspace(static_cast<unsigned char>(b_[u]))) ++u;
    if (u >= b_.size() || b_[u] != '_') fail(u, "<AppendedData>", "the data does not start with '_'");
    appended_ = true, raw_ = encoding == "raw", appended_begin_ = u + 1;
    return b_.size();  // the rest is data
  }
  elements_.push_back(std::move(e));
  if (!empty) open.push_back(name);
  return e.begin;
}

const Element& VtuReader::only(const std::string& name) const {
  const Element* found = nullptr;
  for (const Element& e : elements_)
    if (e.name == name) {
      if (found) fail(e.at, "", "a second <" + name + "> (anisocert reads one of each)");
      found = &e;
    }
  if (!found) fail(b_.size(), "", "there is no <" + name + ">");
  return *found;
}

std::string VtuReader::attribute(const Element& e, const std::string& name, const std::string& fallback) const {
  const auto a = e.attributes.find(name);
  return a == e.attributes.end() ? fallback : a->second;
}

std::int64_t VtuReader::count_attribute(const Element& e, const std::string& name, std::int64_t hi) const {
  const std::string v = attribute(e, name);
  if (v.empty() || v.size() > 12 || !std::all_of(v.begin(), v.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    fail(e.at, "<" + excerpt(e.name) + ">", name + "=" + quoted_excerpt(v) + " is not a count");
  const std::int64_t n = std::stoll(v);
  if (n > hi) fail(e.at, "<" + excerpt(e.name) + ">", name + "=" + excerpt(v) + " is more than " + std::to_string(hi));
  return n;
}

// Bytes of a DataArray in binary or appended form: from base64 text (decoded four characters at a
// time, so that a header and data encoded as two streams read as one) or raw bytes.
class Bytes {
 public:
  Bytes(std::string_view text, bool base64) : text_(text), base64_(base64) {}
  // The next n bytes, or nothing when the data ends first.
  std::optional<std::string> take(std::size_t n) {
    if (!base64_) {
      if (text_.size() - at_ < n) return std::nullopt;
      std::string r(text_.substr(at_, n));
      at_ += n;
      return r;
    }
    while (decoded_.size() - used_ < n) {
      if (!group()) return std::nullopt;
    }
    std::string r = decoded_.substr(used_, n);
    used_ += n;
    return r;
  }
  std::size_t position() const { return at_; }

 private:
  static int value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  }
  // Four characters (blanks skipped) into one to three bytes; false at the end or a bad character.
  bool group() {
    int v[4], n = 0, pad = 0;
    while (n < 4) {
      while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
      if (at_ >= text_.size()) return false;
      const char c = text_[at_];
      if (c == '=' && n >= 2) {
        v[n++] = 0, ++pad, ++at_;
        continue;
      }
      if (pad > 0 || value(c) < 0) return false;
      v[n++] = value(c), ++at_;
    }
    const std::uint32_t w = (static_cast<std::uint32_t>(v[0]) << 18) | (static_cast<std::uint32_t>(v[1]) << 12) |
                            (static_cast<std::uint32_t>(v[2]) << 6) | static_cast<std::uint32_t>(v[3]);
    decoded_.push_back(static_cast<char>((w >> 16) & 0xff));
    if (pad < 2) decoded_.push_back(static_cast<char>((w >> 8) & 0xff));
    if (pad < 1) decoded_.push_back(static_cast<char>(w & 0xff));
    return true;
  }

  std::string_view text_;
  bool base64_;
  std::size_t at_ = 0, used_ = 0;
  std::string decoded_;
};

template <class U>
U load(const char* p, bool big_endian) {
  unsigned char b[sizeof(U)];
  std::memcpy(b, p, sizeof(U));
  if (big_endian != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i < sizeof(U) / 2; ++i) std::swap(b[i], b[sizeof(U) - 1 - i]);
  U v;
  std::memcpy(&v, b, sizeof(U));
  return v;
}

std::string VtuReader::payload(const Element& e, std::size_t bytes) {
  const std::string format = attribute(e, "format", "ascii");
  const std::string context = context_of(e);
  std::optional<Bytes> source;
  std::size_t start = e.begin;
  if (format == "binary") {
    source.emplace(b_.substr(e.begin, text_end(e) - e.begin), true);
  } else {
    if (!appended_) fail(e.at, context, "format=\"appended\" but the file has no <AppendedData>");
    const std::string offset = attribute(e, "offset");
    if (offset.empty() || offset.size() > 18 || !std::all_of(offset.begin(), offset.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      fail(e.at, context, "offset=" + quoted_excerpt(offset) + " is not an offset");
    const std::size_t o = std::stoull(offset);
    if (o > b_.size() - appended_begin_) fail(e.at, context, "offset " + excerpt(offset) + " is beyond the end of the file");
    start = appended_begin_ + o;
    source.emplace(b_.substr(start), !raw_);
  }
  const auto header = [&](const char* what) -> std::uint64_t {
    const auto h = source->take(static_cast<std::size_t>(header_bytes_));
    if (!h) fail(start, context, std::string("the data ends inside the header (") + what + ")");
    return header_bytes_ == 4 ? load<std::uint32_t>(h->data(), big_endian_) : load<std::uint64_t>(h->data(), big_endian_);
  };
  if (!compressed_) {
    if (bytes > b_.size()) fail(start, context, "the file is too short for the array's " + std::to_string(bytes) + " bytes");
    const std::uint64_t n = header("the byte count");
    if (n != bytes) fail(start, context, "the header counts " + std::to_string(n) + " bytes, and the array's values take " + std::to_string(bytes));
    auto data = source->take(bytes);
    if (!data) fail(start, context, "the data ends before its " + std::to_string(bytes) + " bytes");
    return std::move(*data);
  }
  const std::uint64_t blocks = header("the number of blocks"), block_size = header("the block size"), last = header("the last block's size");
  const std::uint64_t last_size = last == 0 ? block_size : last;
  if (blocks == 0 ? bytes != 0 : (blocks > bytes + 1 || block_size == 0 || last_size > block_size || (blocks - 1) * block_size + last_size != bytes))
    fail(start, context, "the compression header (" + std::to_string(blocks) + " blocks of " + std::to_string(block_size) + " bytes, the last of " +
                             std::to_string(last_size) + ") does not hold the array's " + std::to_string(bytes) + " bytes");
  if (blocks > b_.size() / static_cast<std::size_t>(header_bytes_)) fail(start, context, "the file is too short for " + std::to_string(blocks) + " blocks");
  std::vector<std::uint64_t> compressed(static_cast<std::size_t>(blocks));
  for (auto& c : compressed) c = header("a compressed block size");
  std::string out;  // grown block by block: each block's claim is bounded above
  for (std::size_t k = 0; k < compressed.size(); ++k) {
    const std::uint64_t size = k + 1 == compressed.size() ? last_size : block_size;
    // zlib compresses at most 1032:1 (zlib's technical details): a larger claim is refused before
    // any memory is taken for it.
    if (compressed[k] > b_.size() || size > 1032 * compressed[k] + 64)
      fail(start, context, "compressed block " + std::to_string(k + 1) + " of " + std::to_string(compressed[k]) + " bytes cannot hold " + std::to_string(size));
    const auto block = source->take(static_cast<std::size_t>(compressed[k]));
    if (!block) fail(start, context, "the data ends inside compressed block " + std::to_string(k + 1));
    std::string plain(static_cast<std::size_t>(size), '\0');
    uLongf got = static_cast<uLongf>(size);
    const int z = uncompress(reinterpret_cast<Bytef*>(plain.data()), &got, reinterpret_cast<const Bytef*>(block->data()), static_cast<uLong>(block->size()));
    if (z != Z_OK || got != size)
      fail(start, context, "compressed block " + std::to_string(k + 1) + " does not inflate to its " + std::to_string(size) + " bytes (zlib: " +
                               (z == Z_OK ? "it gives " + std::to_string(got) : std::string(zError(z))) + ")");
    out += plain;
  }
  return out;
}

int type_width(const std::string& type) {
  if (type == "Float64" || type == "Int64" || type == "UInt64") return 8;
  if (type == "Float32" || type == "Int32" || type == "UInt32") return 4;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int8" || type == "UInt8") return 1;
  return 0;
}

std::vector<Rational> VtuReader::reals(const Element& e, std::size_t count, int components) {
  const std::string context = context_of(e);
  const std::string given = attribute(e, "NumberOfComponents", "1");
  if (given != std::to_string(components)) fail(e.at, context, "NumberOfComponents is " + quoted_excerpt(given) + ", not " + std::to_string(components));
  const std::string type = attribute(e, "type");
  const std::size_t n = count * static_cast<std::size_t>(components);
  std::vector<Rational> v;  // not reserved from the counts, which the file claims
  if (attribute(e, "format", "ascii") == "ascii") {
    ascii_values(e, n, context, [&](std::string_view t, std::size_t at) {
      try {
        v.push_back(parse_input_number(t));
      } catch (const std::exception& x) {
        fail(at, context, "value " + std::to_string(v.size() + 1) + ": " + x.what());
      }
    });
    return v;
  }
  if (type != "Float32" && type != "Float64") fail(e.at, context, "type " + quoted_excerpt(type) + " is not Float32 or Float64");
  const int w = type_width(type);
  const std::string bytes = payload(e, n * static_cast<std::size_t>(w));
  for (std::size_t k = 0; k < n; ++k) {
    const double x = w == 4 ? static_cast<double>(std::bit_cast<float>(load<std::uint32_t>(bytes.data() + 4 * k, big_endian_)))
                            : std::bit_cast<double>(load<std::uint64_t>(bytes.data() + 8 * k, big_endian_));
    if (!std::isfinite(x)) fail(e.at, context, "value " + std::to_string(k + 1) + " is " + (std::isnan(x) ? "NaN" : "infinite"));
    v.push_back(Rational(x));
  }
  return v;
}

std::vector<std::int64_t> VtuReader::integers(const Element& e, std::size_t count) {
  const std::string context = context_of(e);
  const std::string type = attribute(e, "type");
  const int w = type_width(type);
  if (w == 0 || type.rfind("Float", 0) == 0) fail(e.at, context, "type " + quoted_excerpt(type) + " is not an integer type");
  std::vector<std::int64_t> v;  // not reserved from the counts, which the file claims
  if (attribute(e, "format", "ascii") == "ascii") {
    ascii_values(e, count, context, [&](std::string_view t, std::size_t at) {
      const bool digits = !t.empty() && t.size() <= 18 && std::all_of(t.begin() + (t[0] == '-' ? 1 : 0), t.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
      if (!digits || t == "-") fail(at, context, quoted_excerpt(t) + " is not an integer");
      v.push_back(std::stoll(std::string(t)));
    });
    return v;
  }
  const std::string bytes = payload(e, count * static_cast<std::size_t>(w));
  const bool is_unsigned = type[0] == 'U';
  for (std::size_t k = 0; k < count; ++k) {
    const char* p = bytes.data() + static_cast<std::size_t>(w) * k;
    std::int64_t x = 0;
    switch (w) {
      case 1: x = is_unsigned ? static_cast<std::int64_t>(static_cast<unsigned char>(*p)) : static_cast<std::int64_t>(static_cast<signed char>(*p)); break;
      case 2: x = is_unsigned ? load<std::uint16_t>(p, big_endian_) : load<std::int16_t>(p, big_endian_); break;
      case 4: x = is_unsigned ? static_cast<std::int64_t>(load<std::uint32_t>(p, big_endian_)) : load<std::int32_t>(p, big_endian_); break;
      default: {
        if (is_unsigned && load<std::uint64_t>(p, big_endian_) > static_cast<std::uint64_t>(INT64_MAX))
          fail(e.at, context, "value " + std::to_string(k + 1) + " is beyond 2^63");
        x = load<std::int64_t>(p, big_endian_);
      }
    }
    v.push_back(x);
  }
  return v;
}

std::string text(const Rational& q) { return exact_excerpt(q); }

MeshFile VtuReader::read() {
  scan();
  const Element& file = only("VTKFile");
  if (attribute(file, "type") != "UnstructuredGrid")
    fail(file.at, "<VTKFile>", "type=" + quoted_excerpt(attribute(file, "type")) + ": anisocert reads UnstructuredGrid (.vtu)");
  const std::string order = attribute(file, "byte_order", "LittleEndian");
  if (order != "LittleEndian" && order != "BigEndian") fail(file.at, "<VTKFile>", "byte_order=" + quoted_excerpt(order) + " is neither LittleEndian nor BigEndian");
  big_endian_ = order == "BigEndian";
  const std::string header = attribute(file, "header_type", "UInt32");
  if (header != "UInt32" && header != "UInt64") fail(file.at, "<VTKFile>", "header_type=" + quoted_excerpt(header) + " is neither UInt32 nor UInt64");
  header_bytes_ = header == "UInt64" ? 8 : 4;
  const std::string compressor = attribute(file, "compressor");
  if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
    fail(file.at, "<VTKFile>", "compressor=" + quoted_excerpt(compressor) + ": anisocert reads vtkZLibDataCompressor (zlib) or none");
  compressed_ = !compressor.empty();

  const Element& piece = only("Piece");
  const auto np = static_cast<std::size_t>(count_attribute(piece, "NumberOfPoints", 1LL << 31));
  const auto nc = static_cast<std::size_t>(count_attribute(piece, "NumberOfCells", 1LL << 31));
  const Element *points = nullptr, *connectivity = nullptr, *offsets = nullptr, *types = nullptr, *metric = nullptr;
  for (const Element& e : elements_) {
    if (e.name != "DataArray") continue;
    if (e.end == 0) fail(e.at, context_of(e), "the array is never closed");
    const std::string format = attribute(e, "format", "ascii");
    if (format != "ascii" && format != "binary" && format != "appended")
      fail(e.at, context_of(e), "format=" + quoted_excerpt(format) + " is not ascii, binary or appended");
    std::string name = attribute(e, "Name");
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const Element** slot = e.parent == "Points"                                ? &points
                           : e.parent == "Cells" && name == "connectivity"     ? &connectivity
                           : e.parent == "Cells" && name == "offsets"          ? &offsets
                           : e.parent == "Cells" && name == "types"            ? &types
                           : e.parent == "PointData" && name == "metric"       ? &metric
                                                                               : nullptr;
    if (!slot) continue;
    if (*slot) fail(e.at, context_of(e), "a second such array");
    *slot = &e;
  }
  if (!points) fail(piece.at, "<Piece>", "there is no <Points> array");
  for (const auto& [e, n] : {std::pair{connectivity, "connectivity"}, std::pair{offsets, "offsets"}, std::pair{types, "types"}})
    if (!e) fail(piece.at, "<Cells>", std::string("there is no array named ") + n);

  const std::vector<Rational> xyz = reals(*points, np, 3);
  const std::vector<std::int64_t> type = integers(*types, nc), offset = integers(*offsets, nc);
  std::int64_t previous = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    if (type[c] != vtk_tetra && type[c] != vtk_triangle)
      fail(types->at, context_of(*types), "cell " + std::to_string(c) + " is " + cell_type_name(type[c]) +
                                               ": anisocert reads tetrahedra (type 10) and triangles (type 5)");
    const std::int64_t size = type[c] == vtk_tetra ? 4 : 3;
    if (offset[c] != previous + size)
      fail(offsets->at, context_of(*offsets), "cell " + std::to_string(c) + " ends at " + std::to_string(offset[c]) + ", not " +
                                                   std::to_string(previous + size) + " (its type has " + std::to_string(size) + " vertices)");
    previous = offset[c];
  }
  const std::vector<std::int64_t> vertex = integers(*connectivity, static_cast<std::size_t>(previous));
  for (std::size_t k = 0; k < vertex.size(); ++k)
    if (vertex[k] < 0 || static_cast<std::size_t>(vertex[k]) >= np)
      fail(connectivity->at, context_of(*connectivity), "entry " + std::to_string(k) + " is vertex " + std::to_string(vertex[k]) + ", not one of the " +
                                                            std::to_string(np) + " points");

  MeshFile f;
  const bool tetrahedral = std::find(type.begin(), type.end(), vtk_tetra) != type.end();
  f.dimension = tetrahedral ? 3 : 2;
  std::size_t k = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    const auto v = [&](std::size_t i) { return static_cast<int>(vertex[k + i]); };
    if (type[c] == vtk_tetra) f.mesh3.tetrahedra.push_back({v(0), v(1), v(2), v(3)}), f.tetrahedron_refs.push_back(0);
    else if (tetrahedral) f.mesh3.triangles.push_back({v(0), v(1), v(2)}), f.triangle_refs.push_back(0);
    else f.mesh.triangles.push_back({v(0), v(1), v(2)}), f.triangle_refs.push_back(0);
    k += type[c] == vtk_tetra ? 4 : 3;
  }
  for (std::size_t p = 0; p < np; ++p) {
    if (tetrahedral) {
      f.mesh3.vertices.push_back({xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]});
    } else {
      if (xyz[3 * p + 2] != 0)
        fail(points->at, context_of(*points), "point " + std::to_string(p) + " has z = " + text(xyz[3 * p + 2]) +
                                                  " and there is no tetrahedron: a triangle mesh must be planar (every z exactly 0)");
      f.mesh.sites.push_back({xyz[3 * p], xyz[3 * p + 1]});
    }
  }
  f.vertex_refs.assign(np, 0);
  if (!metric) return f;

  const std::string given = attribute(*metric, "NumberOfComponents", "1");
  const std::vector<std::string> allowed = tetrahedral ? std::vector<std::string>{"1", "6", "9"} : std::vector<std::string>{"1", "3", "4"};
  if (std::find(allowed.begin(), allowed.end(), given) == allowed.end())
    fail(metric->at, context_of(*metric), "NumberOfComponents is " + quoted_excerpt(given) + ": a metric has " + (tetrahedral ? "1, 6 or 9" : "1, 3 or 4") +
                                              " in a " + (tetrahedral ? "tetrahedral" : "triangle") + " mesh");
  const int comps = std::stoi(given);
  const std::vector<Rational> m = reals(*metric, np, comps);
  const auto entry = [&](std::size_t p, int i) { return m[p * static_cast<std::size_t>(comps) + static_cast<std::size_t>(i)]; };
  for (std::size_t p = 0; p < np; ++p) {
    const std::string at = "the metric of point " + std::to_string(p);
    if (comps == 1 && entry(p, 0) <= 0) fail(metric->at, context_of(*metric), at + " is a size " + text(entry(p, 0)) + ", not positive");
    const auto asymmetric = [&](int i, int j) {
      if (entry(p, i) != entry(p, j))
        fail(metric->at, context_of(*metric), at + " is not symmetric: value " + std::to_string(i + 1) + " is " + text(entry(p, i)) +
                                                  " but value " + std::to_string(j + 1) + " is " + text(entry(p, j)));
    };
    if (tetrahedral) {
      Sym3<Rational> M;
      if (comps == 1) M = metric3_of_size(entry(p, 0));
      else if (comps == 6) M = {entry(p, 0), entry(p, 3), entry(p, 5), entry(p, 1), entry(p, 4), entry(p, 2)};
      else asymmetric(1, 3), asymmetric(2, 6), asymmetric(5, 7), M = {entry(p, 0), entry(p, 1), entry(p, 2), entry(p, 4), entry(p, 5), entry(p, 8)};
      if (!predicates::positive_definite(M)) fail(metric->at, context_of(*metric), at + " is not positive definite");
      f.mesh3.metrics.push_back(M);
    } else {
      Sym2<Rational> M;
      if (comps == 1) M = metric_of_size(entry(p, 0));
      else if (comps == 3) M = {entry(p, 0), entry(p, 2), entry(p, 1)};
      else asymmetric(1, 2), M = {entry(p, 0), entry(p, 1), entry(p, 3)};
      if (!positive_definite(M)) fail(metric->at, context_of(*metric), at + " is not positive definite");
      f.mesh.metrics.push_back(M);
    }
  }
  return f;
}

}  // namespace

MeshFile read_vtu(std::string_view bytes, const std::string& source) { return VtuReader(bytes, source).read(); }

MeshFile read_vtu_file(const std::string& path) { return read_vtu(read_whole_file(path), path); }

std::string vtu_text(const MeshFile& m) {
  const bool three = m.dimension == 3;
  const std::size_t np = three ? m.mesh3.vertices.size() : m.mesh.sites.size();
  const std::size_t nt = three ? m.mesh3.tetrahedra.size() + m.mesh3.triangles.size() : m.mesh.triangles.size();
  std::ostringstream o;
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << np << "\" NumberOfCells=\"" << nt << "\">\n"
    << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t p = 0; p < np; ++p) {
    const std::string at = "point " + std::to_string(p);
    if (three) {
      const auto& v = m.mesh3.vertices[p];
      o << decimal_text(v.x, at + " x") << ' ' << decimal_text(v.y, at + " y") << ' ' << decimal_text(v.z, at + " z") << '\n';
    } else {
      const auto& v = m.mesh.sites[p];
      o << decimal_text(v.x, at + " x") << ' ' << decimal_text(v.y, at + " y") << " 0\n";
    }
  }
  o << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  const auto cells = [&](auto&& each) {
    if (three) {
      for (const auto& t : m.mesh3.tetrahedra) each(std::vector<int>(t.begin(), t.end()), vtk_tetra);
      for (const auto& t : m.mesh3.triangles) each(std::vector<int>(t.begin(), t.end()), vtk_triangle);
    } else {
      for (const auto& t : m.mesh.triangles) each(std::vector<int>(t.begin(), t.end()), vtk_triangle);
    }
  };
  cells([&](const std::vector<int>& v, std::int64_t) {
    for (std::size_t i = 0; i < v.size(); ++i) o << (i ? " " : "") << v[i];
    o << '\n';
  });
  o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::int64_t end = 0;
  cells([&](const std::vector<int>& v, std::int64_t) { o << (end += static_cast<std::int64_t>(v.size())) << '\n'; });
  o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  cells([&](const std::vector<int>&, std::int64_t t) { o << t << '\n'; });
  o << "</DataArray>\n</Cells>\n";
  const bool metrics = three ? !m.mesh3.metrics.empty() : !m.mesh.metrics.empty();
  if (metrics) {
    o << "<PointData Tensors=\"metric\">\n<DataArray type=\"Float64\" Name=\"metric\" NumberOfComponents=\"" << (three ? 6 : 3) << "\" format=\"ascii\">\n";
    for (std::size_t p = 0; p < np; ++p) {
      const std::string at = "the metric of point " + std::to_string(p);
      if (three) {
        const auto& M = m.mesh3.metrics[p];
        for (const Rational* x : {&M.m11, &M.m22, &M.m33, &M.m12, &M.m23, &M.m13}) o << decimal_text(*x, at) << (x == &M.m13 ? '\n' : ' ');
      } else {
        const auto& M = m.mesh.metrics[p];
        o << decimal_text(M.m11, at) << ' ' << decimal_text(M.m22, at) << ' ' << decimal_text(M.m12, at) << '\n';
      }
    }
    o << "</DataArray>\n</PointData>\n";
  }
  o << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return o.str();
}

std::vector<FileText> write_vtu_file(const MeshFile& m, const std::string& path) { return {{path, vtu_text(m)}}; }

}  // namespace anisocert::io
