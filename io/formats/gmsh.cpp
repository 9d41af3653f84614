// Gmsh .msh (gmsh.hpp). The specification is the Gmsh reference manual, § "MSH file format" (4.1)
// and § "Legacy formats" (2.2); each function cites the section it reads or writes. Where the
// manual is silent, gmsh 4.8.4's own files decide (tests/formats/peers/gmsh): a binary file keeps
// its section names and the $MeshFormat and $NodeData headers as text lines, and a binary
// $NodeData record starts with an int node tag.
// Beyond gmsh.hpp's summary: triangles get their reference as edges do (triangle_refs); with
// 4-node tetrahedra (type 4) the mesh is tetrahedral (issue 39), its triangles the declared
// boundary and interface faces, otherwise every z must be 0; the metric is the first $NodeData
// view with 1, 3 or 9 components (1 or 9 for tetrahedra; other views are skipped); the
// lines of a partitioned mesh that lie on a partition interface are no boundary and are skipped;
// the writer puts the triangles of each distinct reference on a surface of their own.
#include "io/formats/gmsh.hpp"

#include "io/formats/binary_reader.hpp"
#include "io/formats/text_reader.hpp"
#include "numbers/excerpt.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <unordered_map>

namespace anisocert::io {
namespace {
namespace gmsh_format {  // io/ is one unity-build unit: these names stay apart from the other formats'

using Metric = predicates::Sym2<Rational>;
using Metric3 = predicates::Sym3<Rational>;

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// § "elm-type": the number of nodes of each element type the manual lists (1 2-node line, 2
// 3-node triangle, 3 4-node quadrangle, ..., 15 1-node point, ..., 93 125-node hexahedron); 0 for
// a type it does not list.
int nodes_of_type(std::int32_t type) {
  static constexpr std::array<int, 32> listed{0, 2,  3,  4,  4,  8,  6,  5,  3,  6, 9,  10, 27, 18, 14, 1,
                                              8, 20, 15, 13, 9,  10, 12, 15, 15, 21, 4,  5,  6,  20, 35, 56};
  if (type == 92) return 64;
  if (type == 93) return 125;
  return type >= 0 && type < static_cast<std::int32_t>(listed.size()) ? listed[static_cast<std::size_t>(type)] : 0;
}

// The reading of a .msh file, one interface for the two encodings of § MSH file format: the
// binary file has the ASCII file's sections with every size_t, int and double in binary, its
// section names and the $MeshFormat and data-section headers still text. Version 2.2 is read
// through the ASCII one.
class Input {
 public:
  virtual ~Input() = default;
  virtual bool at_end() = 0;                                        // only blanks remain
  virtual std::string_view word(std::string_view what) = 0;         // the next text token
  virtual std::string_view line(std::string_view what) = 0;         // the next non-blank text line
  virtual std::int64_t ascii_int(std::string_view what, std::int64_t lo, std::int64_t hi) = 0;  // "ASCII int"
  virtual void begin_data() = 0;                                    // past the text line that binary data follow
  virtual std::uint64_t size(std::string_view what) = 0;            // size_t
  virtual std::int32_t int32(std::string_view what) = 0;            // int
  virtual std::int64_t data_tag(std::string_view what) = 0;         // a data record's tag: int in binary
  virtual Rational real(std::string_view what) = 0;                 // double
  virtual void skip_reals(std::uint64_t n, std::string_view what) = 0;
  virtual void begin_record() = 0;                                  // an element: one line in ASCII
  virtual void end_record(const std::string& what) = 0;             // fails with what unless the line ends here
  virtual void skip_element(std::int32_t type, std::uint64_t tag) = 0;   // the node tags of an element not kept
  virtual void skip_to_end(const std::string& section) = 0;         // to the line "$End<section>"
  [[noreturn]] virtual void fail(const std::string& what) = 0;
};

class TextInput final : public Input {
 public:
  explicit TextInput(TextReader& r) : r_(r) {}
  bool at_end() override { return r_.at_end(); }
  std::string_view word(std::string_view what) override { return r_.token(what); }
  std::string_view line(std::string_view what) override {
    if (r_.peek().empty()) r_.fail("the file ends where " + std::string(what) + " was expected");
    return r_.rest_of_line();  // from the token peek() reached
  }
  std::int64_t ascii_int(std::string_view what, std::int64_t lo, std::int64_t hi) override { return r_.integer(what, lo, hi); }
  void begin_data() override {}
  std::uint64_t size(std::string_view what) override { return static_cast<std::uint64_t>(r_.integer(what, 0, INT64_MAX)); }
  std::int32_t int32(std::string_view what) override {
    return static_cast<std::int32_t>(r_.integer(what, INT32_MIN, INT32_MAX));
  }
  std::int64_t data_tag(std::string_view what) override { return r_.integer(what, 0, INT64_MAX); }
  Rational real(std::string_view what) override { return r_.number(what); }
  void skip_reals(std::uint64_t n, std::string_view what) override {
    for (std::uint64_t i = 0; i < n; ++i) r_.token(what);
  }
  void begin_record() override {
    r_.peek();  // to the record's first token, so that line() is the record's line
    line_ = r_.line();
  }
  void end_record(const std::string& what) override {
    if (r_.line() != line_) r_.fail(what + " (line " + std::to_string(line_) + ")");
    if (!r_.rest_of_line().empty()) r_.fail(what);
  }
  void skip_element(std::int32_t, std::uint64_t) override { r_.rest_of_line(); }
  void skip_to_end(const std::string& section) override {  // by lines: a quoted name may hold any word
    const std::string end = "$End" + section;
    for (std::string_view t = r_.peek(); t != end; t = r_.peek()) {
      if (t.empty()) r_.fail("the file ends before " + quoted_excerpt(end));
      r_.rest_of_line();
    }
  }
  [[noreturn]] void fail(const std::string& what) override { r_.fail(what); }

 private:
  TextReader& r_;
  int line_ = 0;
};

class BinaryInput final : public Input {
 public:
  BinaryInput(std::string_view bytes, const std::string& source) : bytes_(bytes), r_(bytes, source) {}

  // § $MeshFormat in binary: past its text line (read_format reads it), the int 1 in binary, that
  // gives the file's byte order.
  void read_byte_order() {
    for (const char* what : {"$MeshFormat", "the version", "the file-type", "the data-size"}) word(what);
    begin_data();
    const std::int32_t one = r_.int32("the int 1 that gives the byte order");
    if (one == 0x01000000) r_.set_swapped(true);
    else if (one != 1)
      r_.fail_at(r_.offset() - 4, "the int that gives the byte order is " + std::to_string(one) + ", not 1 in either byte order");
  }

  bool at_end() override {
    skip_blanks();
    return r_.at_end();
  }
  std::string_view word(std::string_view what) override {
    skip_blanks();
    std::size_t end = r_.offset();
    while (end < bytes_.size() && !blank(bytes_[end])) ++end;
    if (end == r_.offset()) r_.fail("the file ends where " + std::string(what) + " was expected");
    return r_.bytes(end - r_.offset(), what);
  }
  std::string_view line(std::string_view what) override {
    skip_blanks();
    if (r_.at_end()) r_.fail("the file ends where " + std::string(what) + " was expected");
    std::size_t end = r_.offset();
    while (end < bytes_.size() && bytes_[end] != '\n') ++end;
    std::string_view l = r_.bytes(end - r_.offset(), what);
    while (!l.empty() && blank(l.back())) l.remove_suffix(1);
    return l;
  }
  std::int64_t ascii_int(std::string_view what, std::int64_t lo, std::int64_t hi) override {
    const std::size_t start = r_.offset();
    const std::string_view t = word(what);
    std::optional<Rational> q;
    try {
      q = parse_rational(t);
    } catch (const NumberSyntaxError&) {
    }
    if (!q || boost::multiprecision::denominator(*q) != 1 || *q < lo || *q > hi)
      r_.fail_at(start, std::string(what) + " is " + quoted_excerpt(t) + ", not an integer in [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + "]");
    return q->convert_to<std::int64_t>();
  }
  void begin_data() override {
    std::size_t at = r_.offset();
    while (at < bytes_.size() && (bytes_[at] == ' ' || bytes_[at] == '\t' || bytes_[at] == '\r')) ++at;
    if (at >= bytes_.size() || bytes_[at] != '\n') r_.fail_at(at, "expected the end of the text line before binary data");
    r_.seek(at + 1, "the binary data");
  }
  std::uint64_t size(std::string_view what) override { return r_.uint64(what); }
  std::int32_t int32(std::string_view what) override { return r_.int32(what); }
  std::int64_t data_tag(std::string_view what) override { return r_.int32(what); }
  Rational real(std::string_view what) override { return r_.real(8, what); }
  void skip_reals(std::uint64_t n, std::string_view what) override {
    if (n > r_.size() / 8) r_.fail("the file ends inside " + std::to_string(n) + " values: " + std::string(what));
    r_.skip(8 * n, what);
  }
  void begin_record() override {}
  void end_record(const std::string&) override {}
  void skip_element(std::int32_t type, std::uint64_t tag) override {
    const int nodes = nodes_of_type(type);
    if (nodes == 0)
      r_.fail("element " + std::to_string(tag) + " has type " + std::to_string(type) +
              ", whose number of nodes the manual does not list: a binary file cannot be read past it");
    r_.skip(8 * static_cast<std::uint64_t>(nodes), "the node tags of element " + std::to_string(tag));
  }
  // A text section ($PhysicalNames, $InterpolationScheme, a comment) in a binary file: every
  // binary section is read by its structure.
  void skip_to_end(const std::string& section) override {
    const std::string end = "$End" + section;
    for (std::size_t at = bytes_.find(end, r_.offset()); at != std::string_view::npos; at = bytes_.find(end, at + 1)) {
      const std::size_t after = at + end.size();
      if ((at == 0 || bytes_[at - 1] == '\n') && (after == bytes_.size() || blank(bytes_[after]))) return r_.seek(at, end);
    }
    r_.fail("the file ends before " + quoted_excerpt(end));
  }
  [[noreturn]] void fail(const std::string& what) override { r_.fail(what); }

 private:
  void skip_blanks() {
    std::size_t at = r_.offset();
    while (at < bytes_.size() && blank(bytes_[at])) ++at;
    r_.seek(at, "blanks");
  }
  std::string_view bytes_;
  BinaryReader r_;
};

// Runs the reading of a section so that its failures say where: TextReader's "SOURCE:LINE: what"
// and BinaryReader's "SOURCE: byte N: what" become "SOURCE:LINE: in $Nodes: what" and "SOURCE:
// byte N: in $Nodes: what".
template <class Read>
void within(const std::string& section, const std::string& source, Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    std::string m = e.what();
    const std::size_t colon = m.compare(0, source.size(), source) == 0 ? m.find(": ", source.size() + 1) : std::string::npos;
    if (colon != std::string::npos) m.insert(colon + 2, "in " + section + ": ");
    throw InputError(m);
  }
}

void expect_end(Input& in, const std::string& section) {
  const std::string end = "$End" + section;
  const std::string_view w = in.word(quoted_excerpt(end));
  if (w != end) in.fail("expected " + quoted_excerpt(end) + ", found " + quoted_excerpt(w));
}

// An entity of $Entities or $PartitionedEntities, as the elements on it need it.
struct Entity {
  int physical = 0;        // its first physical tag, the reference of its elements (0: none)
  bool interface = false;  // a partition's entity inside an entity of higher dimension: no boundary
};

// What the sections give, as they are read.
struct Reading {
  explicit Reading(std::size_t file_size) : reserve_cap(file_size / 8) {}
  MeshFile f;
  std::vector<std::uint64_t> tags;                  // per site: its node tag
  std::unordered_map<std::uint64_t, int> site_of;   // node tag -> site
  std::map<std::pair<int, int>, Entity> entities;  // by (dim, tag), from $Entities and $PartitionedEntities
  bool elements_read = false;
  std::vector<Rational> z;                          // per site
  std::vector<std::array<int, 4>> tetrahedra;       // type 4: then the mesh is tetrahedral
  std::vector<int> tetrahedron_refs;
  std::optional<std::vector<Metric>> metrics;       // from the first $NodeData view that is a metric
  std::optional<std::vector<Metric3>> metrics3;     // the same for a tetrahedral mesh (known from $Elements)
  std::uint64_t reserve_cap;                        // a count from the file reserves no more (8 bytes a node at least)
};

std::size_t capped(const Reading& r, std::uint64_t count) { return static_cast<std::size_t>(std::min(count, r.reserve_cap)); }

std::string node_name(std::int64_t tag) { return "node " + std::to_string(tag); }

// The next node of $Nodes: its tag (positive, not seen before) becomes the next site.
void add_node(Input& in, Reading& r, std::uint64_t tag) {
  if (tag == 0 || tag > static_cast<std::uint64_t>(INT64_MAX))
    in.fail("node tag " + std::to_string(tag) + " is not a positive integer");
  if (r.tags.size() >= static_cast<std::size_t>(INT_MAX)) in.fail("too many nodes");
  if (!r.site_of.emplace(tag, static_cast<int>(r.tags.size())).second)
    in.fail(node_name(static_cast<std::int64_t>(tag)) + " appears twice");
  r.tags.push_back(tag);
}

// A node's x y z (z must be 0 unless the mesh has tetrahedra: decided at the end).
void add_point(Input& in, Reading& r, std::uint64_t tag) {
  const std::string node = node_name(static_cast<std::int64_t>(tag));
  Rational x = in.real("the x of " + node);
  Rational y = in.real("the y of " + node);
  r.z.push_back(in.real("the z of " + node));
  r.f.mesh.sites.push_back({std::move(x), std::move(y)});
}

void reserve_nodes(Reading& r, std::uint64_t count) {
  r.tags.reserve(r.tags.size() + capped(r, count));
  r.f.mesh.sites.reserve(r.tags.capacity());
  r.site_of.reserve(r.tags.capacity());
}

// 2.2 § $Nodes: number-of-nodes, then node-number x-coord y-coord z-coord for each node.
void read_nodes22(Input& in, Reading& r) {
  const std::uint64_t n = in.size("number-of-nodes");
  reserve_nodes(r, n);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t tag = in.size("a node-number");
    add_node(in, r, tag);
    add_point(in, r, tag);
  }
}

// 4.1 § $Nodes: numEntityBlocks numNodes minNodeTag maxNodeTag; each block entityDim entityTag
// parametric numNodesInBlock, its node tags, then for each node x y z and, when parametric, one
// parametric coordinate per dimension of the entity (u, v, w: ignored).
void read_nodes41(Input& in, Reading& r) {
  const std::uint64_t blocks = in.size("numEntityBlocks");
  const std::uint64_t total = in.size("numNodes");
  in.size("minNodeTag");
  in.size("maxNodeTag");
  reserve_nodes(r, total);
  const std::size_t before = r.tags.size();
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::int32_t dim = in.int32("entityDim");
    in.int32("entityTag");
    const std::int32_t parametric = in.int32("parametric");
    if (dim < 0 || dim > 3) in.fail("entityDim " + std::to_string(dim) + " is not 0, 1, 2 or 3");
    if (parametric != 0 && parametric != 1) in.fail("parametric is " + std::to_string(parametric) + ", not 0 or 1");
    const std::uint64_t n = in.size("numNodesInBlock");
    const std::size_t first = r.tags.size();
    for (std::uint64_t i = 0; i < n; ++i) add_node(in, r, in.size("a nodeTag"));
    for (std::size_t i = first; i < r.tags.size(); ++i) {
      add_point(in, r, r.tags[i]);
      in.skip_reals(parametric == 1 ? static_cast<std::uint64_t>(dim) : 0, "a parametric coordinate");
    }
  }
  const std::size_t read = r.tags.size() - before;
  if (read != total) in.fail("numNodes is " + std::to_string(total) + " but the blocks hold " + std::to_string(read) + " nodes");
}

int site_of(Input& in, const Reading& r, std::uint64_t element, std::uint64_t node) {
  const auto it = r.site_of.find(node);
  if (it == r.site_of.end())
    in.fail("element " + std::to_string(element) + " refers to node " + std::to_string(node) + ", which is not in $Nodes");
  return it->second;
}

// The surface and volume elements of § "elm-type" other than the 3-node triangle and the 4-node
// tetrahedron: a mesh holding one is not a mesh of linear simplices, and skipping it would leave a
// hole the certifier would blame on the mesh.
const char* other_element(std::int32_t type) {
  switch (type) {
    case 3: return "a 4-node quadrangle";
    case 5: return "an 8-node hexahedron";
    case 6: return "a 6-node prism";
    case 7: return "a 5-node pyramid";
    case 9: return "a 6-node (second-order) triangle";
    case 10: return "a 9-node quadrangle";
    case 11: return "a 10-node (second-order) tetrahedron";
    case 12: case 17: case 92: case 93: return "a higher-order hexahedron";
    case 13: case 18: return "a higher-order prism";
    case 14: case 19: return "a higher-order pyramid";
    case 16: return "an 8-node quadrangle";
    case 20: case 21: case 22: case 23: case 24: case 25: return "a higher-order triangle";
    case 29: case 30: case 31: return "a higher-order tetrahedron";
    default: return nullptr;
  }
}

// An element's node tags, after its tag: a 2-node line (type 1: a boundary edge), a 3-node
// triangle (type 2) or a 4-node tetrahedron (type 4) is kept with its reference; another surface
// or volume element is refused; any other type (a point) is skipped.
void read_element(Input& in, Reading& r, std::uint64_t tag, std::int32_t type, int ref) {
  if (const char* other = other_element(type))
    in.fail("element " + std::to_string(tag) + " is " + other + " (type " + std::to_string(type) +
            "): anisocert certifies meshes of 3-node triangles or 4-node tetrahedra only");
  if (type != 1 && type != 2 && type != 4) return in.skip_element(type, tag);
  const int k = type == 1 ? 2 : type == 2 ? 3 : 4;
  std::array<int, 4> v{};
  for (int j = 0; j < k; ++j) v[j] = site_of(in, r, tag, in.size("a node tag of element " + std::to_string(tag)));
  in.end_record("element " + std::to_string(tag) + " (type " + std::to_string(type) + ") needs exactly " + std::to_string(k) +
                " node tags on its line");
  if (type == 1) {
    r.f.mesh.edges.emplace_back(v[0], v[1]);
    r.f.edge_refs.push_back(ref);
  } else if (type == 2) {
    r.f.mesh.triangles.push_back({v[0], v[1], v[2]});
    r.f.triangle_refs.push_back(ref);
  } else {
    r.tetrahedra.push_back(v);
    r.tetrahedron_refs.push_back(ref);
  }
}

// 2.2 § $Elements: number-of-elements, then elm-number elm-type number-of-tags < tag > ...
// node-number-list, one element a line; the first tag is the physical entity, the reference.
void read_elements22(Input& in, Reading& r) {
  const std::uint64_t n = in.size("number-of-elements");
  for (std::uint64_t i = 0; i < n; ++i) {
    in.begin_record();
    const std::uint64_t tag = in.size("an elm-number");
    const std::int32_t type = in.int32("the elm-type of element " + std::to_string(tag));
    const std::uint64_t tags = in.size("the number-of-tags of element " + std::to_string(tag));
    int ref = 0;
    for (std::uint64_t j = 0; j < tags; ++j) {
      const std::int32_t t = in.int32("a tag of element " + std::to_string(tag));
      if (j == 0) ref = t;
    }
    read_element(in, r, tag, type, ref);
  }
  r.elements_read = true;
}

// 4.1 § $Elements: numEntityBlocks numElements minElementTag maxElementTag; each block entityDim
// entityTag elementType numElementsInBlock, then elementTag nodeTag ... for each element. The
// reference is the physical tag of the block's entity (0 for none, or no entity); the elements
// on a partition interface are skipped (its lines are inside the domain).
void read_elements41(Input& in, Reading& r) {
  const std::uint64_t blocks = in.size("numEntityBlocks");
  const std::uint64_t total = in.size("numElements");
  in.size("minElementTag");
  in.size("maxElementTag");
  std::uint64_t count = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::int32_t dim = in.int32("entityDim");
    const std::int32_t entity = in.int32("entityTag");
    const std::int32_t type = in.int32("elementType");
    const std::uint64_t n = in.size("numElementsInBlock");
    const auto found = r.entities.find({dim, entity});
    const Entity e = found == r.entities.end() ? Entity{} : found->second;
    for (std::uint64_t i = 0; i < n; ++i) {
      in.begin_record();
      const std::uint64_t tag = in.size("an elementTag");
      e.interface ? in.skip_element(type, tag) : read_element(in, r, tag, type, e.physical);
    }
    count += n;
  }
  if (count != total)
    in.fail("numElements is " + std::to_string(total) + " but the blocks hold " + std::to_string(count) + " elements");
  r.elements_read = true;
}

void skip_ints(Input& in, std::uint64_t n, std::string_view what) {
  for (std::uint64_t i = 0; i < n; ++i) in.int32(what);
}

// One entity of § $Entities: its tag, a point's X Y Z or another entity's bounding box,
// numPhysicalTags physicalTag ..., and (not for a point) numBounding... and their tags. In §
// $PartitionedEntities the tag is followed by parentDim parentTag numPartitions partitionTag ...:
// a partition's entity whose parent has a higher dimension is an interface between partitions.
void read_entity41(Input& in, Reading& r, int dim, bool partitioned) {
  static constexpr std::array<const char*, 4> kinds{"point", "curve", "surface", "volume"};
  const std::int32_t tag = in.int32(std::string("a ") + kinds[static_cast<std::size_t>(dim)] + "Tag");
  const std::string entity = kinds[static_cast<std::size_t>(dim)] + (" " + std::to_string(tag));
  Entity e;
  if (partitioned) {
    e.interface = in.int32("the parentDim of " + entity) > dim;
    in.int32("the parentTag of " + entity);
    skip_ints(in, in.size("the numPartitions of " + entity), "a partitionTag of " + entity);
  }
  in.skip_reals(dim == 0 ? 3 : 6, (dim == 0 ? "the coordinates of " : "the bounding box of ") + entity);
  const std::uint64_t n = in.size("the numPhysicalTags of " + entity);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::int32_t physical = in.int32("a physicalTag of " + entity);
    if (i == 0) e.physical = physical;
  }
  r.entities[{dim, tag}] = e;
  if (dim > 0) skip_ints(in, in.size("the number of bounding entities of " + entity), "a bounding entity tag of " + entity);
}

// 4.1 § $Entities: numPoints numCurves numSurfaces numVolumes, then the entities, by dimension.
// § $PartitionedEntities: numPartitions, numGhostEntities and their ghostEntityTag partition
// pairs, then the same (each entity with its parent and partitions). The elements' references
// come from here, so the section must precede $Elements (as the manual orders them).
void read_entities41(Input& in, Reading& r, bool partitioned) {
  if (r.elements_read) in.fail("the section comes after $Elements, whose references it gives");
  if (partitioned) {
    in.size("numPartitions");
    const std::uint64_t ghosts = in.size("numGhostEntities");
    for (std::uint64_t i = 0; i < ghosts; ++i) {
      in.int32("a ghostEntityTag");
      in.int32("the partition of a ghost entity");
    }
  }
  std::array<std::uint64_t, 4> counts{};
  for (std::uint64_t& c : counts) c = in.size("numPoints, numCurves, numSurfaces or numVolumes");
  for (int dim = 0; dim < 4; ++dim)
    for (std::uint64_t i = 0; i < counts[static_cast<std::size_t>(dim)]; ++i) read_entity41(in, r, dim, partitioned);
}

// § $NodeData, $ElementData, $ElementNodeData (2.2 and 4.1 alike): numStringTags and the string
// tags (a quoted string a line), numRealTags and the real tags, numIntegerTags and the integer
// tags: the time step, the number of components, the number of entities (then the partition, or
// more). All of it is text, in a binary file too.
struct DataHeader {
  std::int64_t components, count;
};

DataHeader read_data_header(Input& in) {
  const std::int64_t strings = in.ascii_int("numStringTags", 0, INT32_MAX);
  for (std::int64_t i = 0; i < strings; ++i) in.line("a string tag");
  const std::int64_t reals = in.ascii_int("numRealTags", 0, INT32_MAX);
  for (std::int64_t i = 0; i < reals; ++i) in.word("a real tag");
  const std::int64_t ints =
      in.ascii_int("numIntegerTags (at least the time step, the number of components and of entities)", 3, INT32_MAX);
  in.ascii_int("the time step", INT32_MIN, INT32_MAX);
  const std::int64_t components = in.ascii_int("the number of components", 1, INT32_MAX);
  const std::int64_t count = in.ascii_int("the number of entities", 0, INT64_MAX);
  for (std::int64_t i = 3; i < ints; ++i) in.ascii_int("an integer tag", INT64_MIN, INT64_MAX);
  in.begin_data();
  return {components, count};
}

// The records of a view that is not read: entityTag value ... ($ElementNodeData: elementTag
// numNodesPerElement value ...), the tags ints in binary.
void skip_data(Input& in, const DataHeader& h, bool per_element_node) {
  for (std::int64_t i = 0; i < h.count; ++i) {
    in.data_tag("an entity tag");
    const std::int32_t nodes = per_element_node ? in.int32("numNodesPerElement") : 1;
    if (nodes < 0) in.fail("numNodesPerElement is " + std::to_string(nodes));
    in.skip_reals(static_cast<std::uint64_t>(nodes) * static_cast<std::uint64_t>(h.components), "a value");
  }
}

std::string values_text(const std::vector<Rational>& v) {
  std::string t;
  for (const Rational& q : v) t += (t.empty() ? "" : ", ") + exact_excerpt(q);
  return "[" + t + "]";
}

// A 9-component tensor row by row must be symmetric exactly.
void check_symmetric(Input& in, const std::string& node, const std::vector<Rational>& v) {
  for (const auto& [i, j] : {std::pair<std::size_t, std::size_t>{1, 3}, {2, 6}, {5, 7}})  // m12 m21, m13 m31, m23 m32
    if (v[i] != v[j])
      in.fail("the tensor of " + node + ", " + values_text(v) + ", is not symmetric: value " + std::to_string(i + 1) +
              " is " + exact_excerpt(v[i]) + " but value " + std::to_string(j + 1) + " is " + exact_excerpt(v[j]));
}

Rational size_of(Input& in, const std::string& node, const Rational& h) {
  if (h <= 0) in.fail("the size of " + node + " is " + exact_excerpt(h) + ", not positive");
  return h;
}

// The metric of a node of a triangle mesh from its values: a size h > 0 (I/h², metric_of_size),
// m11 m12 m22, or a 3×3 tensor row by row, symmetric exactly, whose z row and column the planar
// mesh ignores.
Metric metric_of(Input& in, const std::string& node, const std::vector<Rational>& v) {
  if (v.size() == 1) return metric_of_size(size_of(in, node, v[0]));
  if (v.size() == 3) return {v[0], v[1], v[2]};
  check_symmetric(in, node, v);
  return {v[0], v[1], v[4]};
}

// The metric of a node of a tetrahedral mesh: a size h > 0 (I/h²) or a 3×3 tensor row by row,
// symmetric exactly.
Metric3 metric3_of(Input& in, const std::string& node, const std::vector<Rational>& v) {
  if (v.size() == 1) return metric3_of_size(size_of(in, node, v[0]));
  check_symmetric(in, node, v);
  return {v[0], v[1], v[2], v[4], v[5], v[8]};
}

std::vector<Rational> entries(const Metric& m) { return {m.m11, m.m12, m.m22}; }
std::vector<Rational> entries(const Metric3& m) { return {m.m11, m.m12, m.m13, m.m22, m.m23, m.m33}; }
const char* entry_names(const Metric&) { return "[m11, m12, m22]"; }
const char* entry_names(const Metric3&) { return "[m11, m12, m13, m22, m23, m33]"; }

// One metric view's records: nodeTag value ..., every node exactly one, each metric positive
// definite (exactly: Sylvester's minors).
template <class M, class Of>
std::vector<M> read_metric_view(Input& in, const Reading& r, const DataHeader& h, Of&& of) {
  std::vector<std::optional<M>> of_site(r.tags.size());
  std::vector<Rational> v(static_cast<std::size_t>(h.components));
  for (std::int64_t i = 0; i < h.count; ++i) {
    const std::int64_t tag =
        in.data_tag(("the nodeTag of value " + std::to_string(i + 1) + " of the " + std::to_string(h.count) + " the view declares"));
    const std::string node = node_name(tag);
    const auto site = tag > 0 ? r.site_of.find(static_cast<std::uint64_t>(tag)) : r.site_of.end();
    if (site == r.site_of.end()) in.fail("the view gives a value to " + node + ", which is not in $Nodes");
    std::optional<M>& m = of_site[static_cast<std::size_t>(site->second)];
    if (m) in.fail(node + " has two values");
    for (std::size_t c = 0; c < v.size(); ++c) v[c] = in.real("value " + std::to_string(c + 1) + " of " + node);
    m = of(in, node, v);
    if (!positive_definite(*m))
      in.fail("the metric of " + node + ", " + entry_names(*m) + " = " + values_text(entries(*m)) + " (from " + values_text(v) +
              "), is not positive definite");
  }
  std::vector<M> out;
  out.reserve(of_site.size());
  for (std::size_t s = 0; s < of_site.size(); ++s) {
    if (!of_site[s])
      in.fail(node_name(static_cast<std::int64_t>(r.tags[s])) + " has no value: the view has " + std::to_string(h.count) +
              " values for " + std::to_string(of_site.size()) + " nodes");
    out.push_back(std::move(*of_site[s]));
  }
  return out;
}

// § $NodeData: the metric is the first view with 1, 3 or 9 components (a tetrahedral mesh: 1 or
// 9; its tetrahedra are known, $Elements coming before $NodeData in what gmsh writes). Other views
// are skipped.
void read_node_data(Input& in, Reading& r) {
  const DataHeader h = read_data_header(in);
  const bool three = !r.tetrahedra.empty();
  const bool metric = h.components == 1 || h.components == 9 || (!three && h.components == 3);
  if (r.metrics || r.metrics3 || !metric) return skip_data(in, h, false);
  if (three) r.metrics3 = read_metric_view<Metric3>(in, r, h, metric3_of);
  else r.metrics = read_metric_view<Metric>(in, r, h, metric_of);
}

// 4.1 § $Periodic: numPeriodicLinks; each entityDim entityTag entityTagMaster, numAffine value
// ..., numCorrespondingNodes and their nodeTag nodeTagMaster pairs.
void skip_periodic41(Input& in) {
  const std::uint64_t links = in.size("numPeriodicLinks");
  for (std::uint64_t l = 0; l < links; ++l) {
    skip_ints(in, 3, "entityDim, entityTag or entityTagMaster");
    in.skip_reals(in.size("numAffine"), "an affine value");
    const std::uint64_t nodes = in.size("numCorrespondingNodes");
    for (std::uint64_t i = 0; i < nodes; ++i) {
      in.size("a nodeTag");
      in.size("a nodeTagMaster");
    }
  }
}

// 4.1 § $GhostElements: numGhostElements; each elementTag partitionTag numGhostPartitions
// ghostPartitionTag ....
void skip_ghost_elements41(Input& in) {
  const std::uint64_t n = in.size("numGhostElements");
  for (std::uint64_t i = 0; i < n; ++i) {
    in.size("an elementTag");
    in.int32("a partitionTag");
    skip_ints(in, in.size("numGhostPartitions"), "a ghostPartitionTag");
  }
}

// 4.1 § $Parametrizations: numCurveParam numSurfaceParam; a curve: curveTag numNodes, then
// nodeX nodeY nodeZ nodeU for each node; a surface: surfaceTag numNodes numTriangles, then 11
// reals for each node (X Y Z U V and two curvature directions) and 3 int node indices for each
// triangle.
void skip_parametrizations41(Input& in) {
  const std::uint64_t curves = in.size("numCurveParam");
  const std::uint64_t surfaces = in.size("numSurfaceParam");
  for (std::uint64_t c = 0; c < curves; ++c) {
    in.int32("a curveTag");
    const std::uint64_t nodes = in.size("numNodes");
    for (std::uint64_t i = 0; i < nodes; ++i) in.skip_reals(4, "nodeX nodeY nodeZ nodeU");
  }
  for (std::uint64_t s = 0; s < surfaces; ++s) {
    in.int32("a surfaceTag");
    const std::uint64_t nodes = in.size("numNodes");
    const std::uint64_t triangles = in.size("numTriangles");
    for (std::uint64_t i = 0; i < nodes; ++i) in.skip_reals(11, "the parametrization of a node");
    for (std::uint64_t i = 0; i < triangles; ++i) skip_ints(in, 3, "a nodeIndex");
  }
}

// One section, after its name; its "$End" line is left to the caller. The sections the reader
// does not use are skipped: by their structure when 4.1 defines one (a binary file may hold any
// byte), by their "$End" line otherwise ($PhysicalNames, $InterpolationScheme, comments: text in
// both encodings; 2.2's $Periodic).
void read_section(Input& in, int version, const std::string& section, Reading& r) {
  const bool v41 = version == 41;
  if (section == "Nodes") v41 ? read_nodes41(in, r) : read_nodes22(in, r);
  else if (section == "Elements") v41 ? read_elements41(in, r) : read_elements22(in, r);
  else if (v41 && (section == "Entities" || section == "PartitionedEntities")) read_entities41(in, r, section != "Entities");
  else if (section == "NodeData") read_node_data(in, r);
  else if (section == "ElementData") skip_data(in, read_data_header(in), false);
  else if (section == "ElementNodeData") skip_data(in, read_data_header(in), true);
  else if (v41 && section == "Periodic") skip_periodic41(in);
  else if (v41 && section == "GhostElements") skip_ghost_elements41(in);
  else if (v41 && section == "Parametrizations") skip_parametrizations41(in);
  else in.skip_to_end(section);
}

// § MSH file format: after $MeshFormat, sections "$Name" ... "$EndName" to the end of the file.
void read_sections(Input& in, const std::string& source, int version, Reading& r) {
  while (!in.at_end()) {
    const std::string name(in.word("a section"));
    if (name.size() < 2 || name[0] != '$') in.fail("expected a section \"$Name\", found " + quoted_excerpt(name));
    within(excerpt(name), source, [&] {  // a binary file may put any byte in a section's name
      in.begin_data();
      read_section(in, version, name.substr(1), r);
      expect_end(in, name.substr(1));
    });
  }
}

// § $MeshFormat: version (ASCII double: 2.2 or 4.1 here) file-type (0 ASCII, 1 binary: 4.1
// only) data-size (8: the size of 4.1's size_t, of 2.2's double).
struct Format {
  int version;  // 22 or 41
  bool binary;
};

Format read_format(TextReader& text) {
  const std::string_view v = text.token("the version");
  std::optional<Rational> q;
  try {
    q = parse_rational(v);
  } catch (const NumberSyntaxError&) {
  }
  const int version = q == Rational(22, 10) ? 22 : q == Rational(41, 10) ? 41 : 0;
  if (version == 0) text.fail("version " + quoted_excerpt(v) + " is not supported (2.2 and 4.1 are)");
  const bool binary = text.integer("the file-type", 0, 1) == 1;
  const std::int64_t data_size = text.integer("the data-size", INT64_MIN, INT64_MAX);
  if (data_size != 8) text.fail("data-size " + std::to_string(data_size) + " is not supported (8 is)");
  if (binary && version == 22) text.fail("binary MSH 2.2 is not supported (2.2 ASCII and 4.1 ASCII or binary are)");
  return {version, binary};
}

// § MSH file format: $MeshFormat first, its text line telling the version and the encoding; then
// the sections. Sites have no reference (vertex_refs all 0).
MeshFile read(std::string_view bytes, const std::string& source, bool surface) {
  TextReader text(bytes, source);
  text.expect("$MeshFormat");
  Format format{};
  within("$MeshFormat", source, [&] { format = read_format(text); });
  TextInput ascii(text);
  BinaryInput binary(bytes, source);
  Input& in = format.binary ? static_cast<Input&>(binary) : ascii;
  within("$MeshFormat", source, [&] {
    if (format.binary) binary.read_byte_order();
    expect_end(in, "MeshFormat");
  });
  Reading r(bytes.size());
  read_sections(in, source, format.version, r);
  r.f.vertex_refs.assign(r.f.mesh.sites.size(), 0);
  if (!r.tetrahedra.empty()) {  // a tetrahedral mesh: its triangles are the declared boundary (or interface) faces
    if (r.metrics) throw InputError(source + ": the metric view comes before the tetrahedra of $Elements, and was read as 2D");
    MeshFile& f = r.f;
    f.dimension = 3;
    f.mesh3.vertices.reserve(f.mesh.sites.size());
    for (std::size_t i = 0; i < f.mesh.sites.size(); ++i)
      f.mesh3.vertices.push_back({std::move(f.mesh.sites[i].x), std::move(f.mesh.sites[i].y), std::move(r.z[i])});
    f.mesh.sites.clear();
    f.mesh3.tetrahedra = std::move(r.tetrahedra);
    f.tetrahedron_refs = std::move(r.tetrahedron_refs);
    f.mesh3.triangles = std::move(f.mesh.triangles);
    f.mesh.triangles.clear();
    if (r.metrics3) attach_metrics(f, std::move(*r.metrics3), source);
    return std::move(r.f);
  }
  if (surface) {  // a surface: the triangles in space
    MeshFile& f = r.f;
    f.dimension = 3;
    for (std::size_t i = 0; i < f.mesh.sites.size(); ++i)
      f.mesh3.vertices.push_back({std::move(f.mesh.sites[i].x), std::move(f.mesh.sites[i].y), std::move(r.z[i])});
    f.mesh.sites.clear();
    f.mesh3.triangles = std::move(f.mesh.triangles);
    f.mesh.triangles.clear();
    return std::move(r.f);
  }
  for (std::size_t i = 0; i < r.z.size(); ++i)
    if (r.z[i] != 0)
      throw InputError(source + ": " + node_name(static_cast<std::int64_t>(r.tags[i])) + " has z = " + exact_excerpt(r.z[i]) +
                       ", and there is no tetrahedron: the mesh must be planar (every z exactly 0) or tetrahedral");
  if (r.metrics) attach_metrics(r.f, std::move(*r.metrics), source);
  return std::move(r.f);
}

// The MSH 4.1 writer's two encodings: the same sections, each size_t, int and double in binary
// (in the machine's byte order, as gmsh writes them) or as ASCII text, values separated by a
// blank and records by a line.
class Output {
 public:
  explicit Output(bool binary) : binary_(binary) {}
  void text(std::string_view s) { out_ += s; }
  void size(std::uint64_t v) { binary_ ? raw(v) : ascii(std::to_string(v)); }
  void int32(std::int32_t v) { binary_ ? raw(v) : ascii(std::to_string(v)); }
  void real(const Rational& q, const std::string& what) {
    binary_ ? raw(exact_double(q, what)) : ascii(decimal_text(q, what));
  }
  void end_record() {
    if (!binary_) out_.back() = '\n';  // the blank after the record's last value
  }
  void begin(const std::string& section) { text("$" + section + "\n"); }
  void end(const std::string& section) { text((binary_ ? "\n$End" : "$End") + section + "\n"); }
  bool binary() const { return binary_; }
  std::string str() && { return std::move(out_); }

 private:
  template <class T>
  void raw(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out_.append(b, sizeof(T));
  }
  void ascii(const std::string& s) { out_ += s + ' '; }
  bool binary_;
  std::string out_;
};

int ref_of(const std::vector<int>& refs, std::size_t i) { return i < refs.size() ? refs[i] : 0; }

// The entity of each distinct reference of n elements, numbered from 1 by increasing reference
// (a reference missing from refs is 0).
std::map<int, std::int32_t> entities_of(const std::vector<int>& refs, std::size_t n) {
  std::map<int, std::int32_t> entities;
  for (std::size_t i = 0; i < n; ++i) entities.emplace(ref_of(refs, i), 0);
  std::int32_t tag = 0;
  for (auto& [ref, entity] : entities) entity = ++tag;
  return entities;
}

// What the writer puts in the file, the same for a triangle mesh and a tetrahedral one: the
// nodes' x y z (z = 0 in 2D), the lines, triangles and tetrahedra with their references.
struct Shape {
  std::vector<std::array<Rational, 3>> points;
  const std::vector<std::array<int, 3>>* triangles;
  const std::vector<std::array<int, 4>>* tetrahedra;  // empty for a triangle mesh
};

Shape shape_of(const MeshFile& m) {
  Shape s{{}, m.dimension == 3 ? &m.mesh3.triangles : &m.mesh.triangles, &m.mesh3.tetrahedra};
  if (m.dimension == 3)
    for (const auto& p : m.mesh3.vertices) s.points.push_back({p.x, p.y, p.z});
  else
    for (const auto& p : m.mesh.sites) s.points.push_back({p.x, p.y, Rational(0)});
  return s;
}

// § $Entities: one curve per edge reference, one surface per triangle reference, one volume per
// tetrahedron reference (one surface or volume, that holds the nodes, when there is no element
// of the mesh's dimension), the reference as the entity's physical tag (none for 0); no points,
// no bounding entities; each entity's box is the mesh's.
void write_entities(Output& out, const Shape& shape, const std::array<std::map<int, std::int32_t>, 3>& entities) {
  std::array<Rational, 6> box{};  // minX minY minZ maxX maxY maxZ
  for (std::size_t i = 0; i < shape.points.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const Rational& q = shape.points[i][c];
      box[c] = i == 0 ? q : std::min(box[c], q);
      box[c + 3] = i == 0 ? q : std::max(box[c + 3], q);
    }
  out.begin("Entities");
  out.size(0);
  for (const auto& e : entities) out.size(e.size());
  out.end_record();
  for (const auto& e : entities)
    for (const auto& [ref, tag] : e) {
      out.int32(tag);
      for (const Rational& q : box) out.real(q, "a coordinate of the bounding box");
      out.size(ref == 0 ? 0 : 1);
      if (ref != 0) out.int32(ref);
      out.size(0);
      out.end_record();
    }
  out.end("Entities");
}

// § $Nodes: one block, on the first entity of the mesh's dimension; site i is node i + 1.
void write_nodes(Output& out, const Shape& shape, std::int32_t dim, std::int32_t entity) {
  const std::uint64_t n = shape.points.size();
  out.begin("Nodes");
  for (std::uint64_t v : {std::uint64_t{1}, n, std::uint64_t{n > 0}, n}) out.size(v);
  out.end_record();
  for (std::int32_t v : {dim, entity, 0}) out.int32(v);
  out.size(n);
  out.end_record();
  for (std::uint64_t i = 1; i <= n; ++i) {
    out.size(i);
    out.end_record();
  }
  for (std::size_t i = 0; i < shape.points.size(); ++i) {
    const std::string what = "a coordinate of site " + std::to_string(i);
    for (const Rational& q : shape.points[i]) out.real(q, what);
    out.end_record();
  }
  out.end("Nodes");
}

// A block of § $Elements: consecutive elements with one reference (the file keeps their order).
struct Block {
  std::int32_t dim, entity;  // 1: lines (elementType 1); 2: triangles (type 2); 3: tetrahedra (type 4)
  std::size_t first, count;
};

std::vector<Block> blocks_of(std::int32_t dim, const std::vector<int>& refs, std::size_t n,
                             const std::map<int, std::int32_t>& entities) {
  std::vector<Block> blocks;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 || ref_of(refs, i) != ref_of(refs, i - 1)) blocks.push_back({dim, entities.at(ref_of(refs, i)), i, 0});
    ++blocks.back().count;
  }
  return blocks;
}

// § $Elements: the edges as 2-node lines on their curves, the triangles on their surfaces, the
// tetrahedra in their volumes; element tags 1, 2, ... in that order.
void write_elements(Output& out, const MeshFile& m, const Shape& shape, const std::array<std::map<int, std::int32_t>, 3>& entities) {
  std::vector<Block> blocks = blocks_of(1, m.edge_refs, m.mesh.edges.size(), entities[0]);
  for (const Block& b : blocks_of(2, m.triangle_refs, shape.triangles->size(), entities[1])) blocks.push_back(b);
  for (const Block& b : blocks_of(3, m.tetrahedron_refs, shape.tetrahedra->size(), entities[2])) blocks.push_back(b);
  const std::uint64_t total = m.mesh.edges.size() + shape.triangles->size() + shape.tetrahedra->size();
  out.begin("Elements");
  for (std::uint64_t v : {std::uint64_t{blocks.size()}, total, std::uint64_t{total > 0}, total}) out.size(v);
  out.end_record();
  std::uint64_t tag = 0;
  const auto node = [&](int v) { out.size(static_cast<std::uint64_t>(v) + 1); };
  for (const Block& b : blocks) {
    for (std::int32_t v : {b.dim, b.entity, b.dim == 3 ? 4 : b.dim}) out.int32(v);
    out.size(b.count);
    out.end_record();
    for (std::size_t i = b.first; i < b.first + b.count; ++i) {
      out.size(++tag);
      if (b.dim == 1) node(m.mesh.edges[i].first), node(m.mesh.edges[i].second);
      else if (b.dim == 2) std::for_each((*shape.triangles)[i].begin(), (*shape.triangles)[i].end(), node);
      else std::for_each((*shape.tetrahedra)[i].begin(), (*shape.tetrahedra)[i].end(), node);
      out.end_record();
    }
  }
  out.end("Elements");
}

// A node's nine values, row by row: 2D m11 m12 0 m12 m22 0 0 0 1; 3D the full tensor.
std::array<const Rational*, 9> nine(const Metric& M) {
  static const Rational zero = 0, one = 1;
  return {&M.m11, &M.m12, &zero, &M.m12, &M.m22, &zero, &zero, &zero, &one};
}
std::array<const Rational*, 9> nine(const Metric3& M) {
  return {&M.m11, &M.m12, &M.m13, &M.m12, &M.m22, &M.m23, &M.m13, &M.m23, &M.m33};
}

// § $NodeData: one view "metric", time 0, step 0, 9 components for each node (its tag an int in
// binary).
template <class M>
void write_metrics(Output& out, const std::vector<M>& metrics) {
  out.begin("NodeData");
  out.text("1\n\"metric\"\n1\n0\n3\n0\n9\n" + std::to_string(metrics.size()) + "\n");
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string what = "the metric of site " + std::to_string(i);
    out.int32(static_cast<std::int32_t>(i + 1));
    for (const Rational* q : nine(metrics[i])) out.real(*q, what);
    out.end_record();
  }
  out.end("NodeData");
}

// § MSH file format: $MeshFormat (4.1), $Entities, $Nodes, $Elements, and $NodeData when the mesh
// has metrics.
std::string write(const MeshFile& m, bool binary) {
  const Shape shape = shape_of(m);
  const std::size_t metrics = m.dimension == 3 ? m.mesh3.metrics.size() : m.mesh.metrics.size();
  if (metrics != 0 && metrics != shape.points.size())
    throw InputError("Gmsh: " + std::to_string(metrics) + " metrics for a mesh of " + std::to_string(shape.points.size()) +
                     " vertices");
  Output out(binary);
  out.text(out.binary() ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n");
  if (out.binary()) out.int32(1);  // § $MeshFormat: the int 1, that gives the byte order
  out.end("MeshFormat");
  std::array<std::map<int, std::int32_t>, 3> entities{entities_of(m.edge_refs, m.mesh.edges.size()),
                                                      entities_of(m.triangle_refs, shape.triangles->size()),
                                                      entities_of(m.tetrahedron_refs, shape.tetrahedra->size())};
  const std::size_t top = m.dimension == 3 ? 2 : 1;  // the entities of the mesh's dimension, which hold the nodes
  if (entities[top].empty()) entities[top].emplace(0, 1);
  write_entities(out, shape, entities);
  write_nodes(out, shape, static_cast<std::int32_t>(top + 1), entities[top].begin()->second);
  write_elements(out, m, shape, entities);
  if (m.dimension == 3 && metrics != 0) write_metrics(out, m.mesh3.metrics);
  if (m.dimension != 3 && metrics != 0) write_metrics(out, m.mesh.metrics);
  return std::move(out).str();
}

}  // namespace gmsh_format
}  // namespace

bool looks_like_gmsh(std::string_view head) {
  std::size_t i = 0;
  while (i < head.size() && gmsh_format::blank(head[i])) ++i;
  return head.substr(i).starts_with("$MeshFormat");
}

MeshFile read_gmsh(std::string_view bytes, const std::string& source, bool surface) { return gmsh_format::read(bytes, source, surface); }

MeshFile read_gmsh_file(const std::string& path, bool surface) { return read_gmsh(read_whole_file(path), path, surface); }

std::string gmsh_text(const MeshFile& m, GmshEncoding encoding) {
  return gmsh_format::write(m, encoding == GmshEncoding::binary);
}

std::vector<FileText> write_gmsh_file(const MeshFile& m, const std::string& path) { return {{path, gmsh_text(m)}}; }

}  // namespace anisocert::io
