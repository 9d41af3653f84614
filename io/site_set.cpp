// Reads and validates the site-set input file (DESIGN.md § Command line and files): numbers are
// exact from their text, geometry checks are exact rational predicates with no tolerance.

#include "io/site_set.hpp"

#include "predicates/orientation.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <map>
#include <numeric>
#include <optional>

namespace anisocert::io {
namespace {

using Json = nlohmann::json;
using Point = predicates::Point2<Rational>;
using predicates::orientation;

// ---- the document -------------------------------------------------------------------------------

// Builds the document like nlohmann's own DOM parser, except that
//  - a number with a fraction or an exponent (or too large for 64 bits) is kept as its text, a
//    JSON string, so that parse_rational reads it exactly (the JSON number 0.1 becomes "0.1");
//    integers that fit in 64 bits are kept as JSON integers, which are exact;
//  - a key repeated within one object is an error instead of silently keeping the last value.
class ExactDocument : public nlohmann::json_sax<Json> {
 public:
  explicit ExactDocument(const std::string& source) : source_(source) {}
  Json take() { return std::move(root_); }

  bool null() override { return add(nullptr); }
  bool boolean(bool b) override { return add(b); }
  bool number_integer(number_integer_t n) override { return add(n); }
  bool number_unsigned(number_unsigned_t n) override { return add(n); }
  bool number_float(number_float_t, const string_t& lexeme) override { return add(lexeme); }
  bool string(string_t& s) override { return add(std::move(s)); }
  bool binary(binary_t& b) override { return add(Json::binary(std::move(b))); }
  bool start_object(std::size_t) override { return open(Json::object()); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    if (open_.back()->contains(k)) {
      const std::string where = path();
      throw InputError(source_ + ": " + (where.empty() ? "" : where + ": ") + "key " + Json(k).dump() +
                       " appears twice");
    }
    keys_.back() = std::move(k);
    return true;
  }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at line 1, ..."
    if (const auto end_of_id = what.find("] "); end_of_id != std::string::npos) what.erase(0, end_of_id + 2);
    throw InputError(source_ + ": invalid JSON at byte " + std::to_string(position) + ": " + what);
  }

 private:
  // Places v in the innermost open container (or as the root) and returns where it now lives.
  // Pointers to open containers stay valid: only the innermost one grows.
  Json* place(Json v) {
    if (open_.empty()) return &(root_ = std::move(v));
    Json& container = *open_.back();
    if (container.is_array()) {
      container.push_back(std::move(v));
      return &container.back();
    }
    return &(container[keys_.back()] = std::move(v));
  }
  bool add(Json v) {
    place(std::move(v));
    return true;
  }
  bool open(Json empty) {
    open_.push_back(place(std::move(empty)));
    keys_.emplace_back();
    return true;
  }
  bool close() {
    open_.pop_back();
    keys_.pop_back();
    return true;
  }
  // The path of the innermost open container, "sites[3]" style.
  std::string path() const {
    std::string p;
    for (std::size_t k = 0; k + 1 < open_.size(); ++k)
      p += open_[k]->is_array() ? "[" + std::to_string(open_[k]->size() - 1) + "]"
                                : (p.empty() ? "" : ".") + keys_[k];
    return p;
  }

  std::string source_;
  Json root_;
  std::vector<Json*> open_;        // the containers being filled, outermost first
  std::vector<std::string> keys_;  // per open object, the key of the value being filled
};

// ---- text of values in messages ----------------------------------------------------------------

// The JSON text of v on one line, cut after about 60 bytes (never inside a UTF-8 sequence).
std::string show(const Json& v) {
  std::string s = v.dump();
  if (s.size() <= 60) return s;
  std::size_t cut = 57;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
  return s.substr(0, cut) + "...";
}

std::string show(const Point& p) { return "(" + to_exact_string(p.x) + ", " + to_exact_string(p.y) + ")"; }

std::string index(const std::string& array, std::size_t i) { return array + "[" + std::to_string(i) + "]"; }

// ---- exact polygon geometry --------------------------------------------------------------------

// p on the closed segment [a, b].
bool on_segment(const Point& p, const Point& a, const Point& b) {
  return orientation(a, b, p) == Sign::zero && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Where the closed segments [p1, p2] and [q1, q2] meet, if they do: the crossing point of a
// proper crossing, otherwise an endpoint of one lying on the other (touching or overlapping).
struct Meeting {
  bool crossing;
  Point at;
};
std::optional<Meeting> segments_meet(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const Sign o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const Sign o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 * o2 == Sign::negative && o3 * o4 == Sign::negative) {
    // p1 + t (p2 − p1) with t = P(q1, q2, p1) / (P(q1, q2, p1) − P(q1, q2, p2)), P the orientation
    // polynomial; the denominator is non-zero since the two values have opposite signs.
    const auto P = [](const Point& a, const Point& b, const Point& c) {
      return predicates::OrientationKernel::eval<Rational>({a.x, a.y, b.x, b.y, c.x, c.y});
    };
    const Rational s = P(q1, q2, p1), t = s / (s - P(q1, q2, p2));
    return Meeting{true, Point{p1.x + t * (p2.x - p1.x), p1.y + t * (p2.y - p1.y)}};
  }
  if (on_segment(q1, p1, p2)) return Meeting{false, q1};
  if (on_segment(q2, p1, p2)) return Meeting{false, q2};
  if (on_segment(p1, q1, q2)) return Meeting{false, p1};
  if (on_segment(p2, q1, q2)) return Meeting{false, p2};
  return std::nullopt;
}

// p in the closed polygon: on an edge, or inside by the crossing number of the ray from p towards
// +x (an edge counts when one endpoint is strictly above p and the other is not).
bool in_closed_polygon(const Point& p, const std::vector<Point>& polygon) {
  const std::size_t m = polygon.size();
  bool inside = false;
  for (std::size_t k = 0; k < m; ++k) {
    const Point& a = polygon[k];
    const Point& b = polygon[(k + 1) % m];
    if (on_segment(p, a, b)) return true;
    // p is off the edge, so it is strictly left or right of an edge that spans its height; the
    // crossing is to the right of p when p is left of an upward edge or right of a downward one.
    if ((a.y > p.y) != (b.y > p.y) && (orientation(a, b, p) == Sign::positive) == (a.y < b.y)) inside = !inside;
  }
  return inside;
}

// ---- the reader ---------------------------------------------------------------------------------

class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  // A domain file for the refiners: {"domain": [...]} (other keys of the site-set format allowed).
  std::vector<Point> read_domain_only(const Json& doc) const {
    if (!doc.is_object()) fail("", "the top level must be an object, got " + show(doc));
    require_keys(doc, "", {"domain"}, {"sites", "domain", "segments", "triangles"});
    return read_domain(doc.at("domain"));
  }

  SiteSet read(const Json& doc) const {
    if (!doc.is_object()) fail("", "the top level must be an object, got " + show(doc));
    require_keys(doc, "", {"sites"}, {"sites", "domain", "segments", "triangles"});
    SiteSet set;
    read_sites(doc.at("sites"), set);
    require_distinct_sites(set.sites);
    if (doc.contains("domain")) {
      set.domain = read_domain(doc.at("domain"));
      set.domain_given = true;
      for (std::size_t i = 0; i < set.sites.size(); ++i)
        if (!in_closed_polygon(set.sites[i], set.domain))
          fail("", index("sites", i) + " " + show(set.sites[i]) + " lies outside the domain");
    } else {
      set.domain = default_box(set.sites);
    }
    if (doc.contains("segments")) set.segments = read_segments(doc.at("segments"), set.sites.size());
    if (doc.contains("triangles")) set.triangles = read_triangles(doc.at("triangles"), set.sites.size());
    return set;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(source_ + ": " + (path.empty() ? "" : path + ": ") + what);
  }

  void require_keys(const Json& object, const std::string& path, std::initializer_list<const char*> required,
                    std::initializer_list<const char*> allowed) const {
    std::string expected;
    for (const char* k : allowed) expected += (expected.empty() ? "" : ", ") + std::string(k);
    for (const auto& item : object.items())
      if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
        fail(path, "unknown key " + Json(item.key()).dump() + " (expected " + expected + ")");
    for (const char* k : required)
      if (!object.contains(k)) fail(path, "missing key \"" + std::string(k) + "\"");
  }

  Rational read_number(const Json& v, const std::string& path) const {
    if (v.is_number_unsigned()) return Rational(Integer(v.get<std::uint64_t>()));
    if (v.is_number_integer()) return Rational(Integer(v.get<std::int64_t>()));
    if (!v.is_string())
      fail(path, "expected a number (a JSON number, or a string holding an integer, fraction or decimal), got " +
                     show(v));
    try {
      return parse_rational(v.get_ref<const std::string&>());
    } catch (const NumberSyntaxError& e) {
      fail(path, e.what());
    }
  }

  // [x, y] or [m11, m12, m22]: an array of exactly n numbers.
  std::vector<Rational> read_numbers(const Json& v, std::size_t n, const std::string& path,
                                     const std::string& expected) const {
    if (!v.is_array() || v.size() != n) fail(path, "expected " + expected + ", got " + show(v));
    std::vector<Rational> q;
    for (std::size_t i = 0; i < n; ++i) q.push_back(read_number(v[i], index(path, i)));
    return q;
  }

  void read_sites(const Json& sites, SiteSet& set) const {
    if (!sites.is_array() || sites.empty()) fail("sites", "expected a non-empty array of sites, got " + show(sites));
    for (std::size_t i = 0; i < sites.size(); ++i) {
      const std::string path = index("sites", i);
      const Json& site = sites[i];
      if (!site.is_object())
        fail(path, "expected an object {\"x\": ..., \"y\": ..., \"metric\": [m11, m12, m22]}, got " + show(site));
      require_keys(site, path, {"x", "y", "metric"}, {"x", "y", "metric"});
      set.sites.push_back(Point{read_number(site.at("x"), path + ".x"), read_number(site.at("y"), path + ".y")});
      const std::vector<Rational> m = read_numbers(site.at("metric"), 3, path + ".metric", "[m11, m12, m22]");
      try {
        set.metrics.emplace_back(predicates::Sym2<Rational>{m[0], m[1], m[2]});
      } catch (const predicates::NotPositiveDefinite& e) {
        fail(path + ".metric", e.what());
      }
    }
  }

  // Sorted by (x, y), coincident sites are neighbours; ties keep index order.
  void require_distinct_sites(const std::vector<Point>& sites) const {
    std::vector<std::size_t> order(sites.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      const Point &p = sites[i], &q = sites[j];
      return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : i < j;
    });
    for (std::size_t k = 1; k < order.size(); ++k) {
      const Point &p = sites[order[k - 1]], &q = sites[order[k]];
      if (p.x == q.x && p.y == q.y)
        fail("", index("sites", order[k - 1]) + " and " + index("sites", order[k]) + " coincide at " + show(p));
    }
  }

  std::vector<Point> read_domain(const Json& domain) const {
    if (!domain.is_array() || domain.size() < 3)
      fail("domain", "expected an array of at least 3 vertices [x, y], got " + show(domain));
    std::vector<Point> v;
    for (std::size_t k = 0; k < domain.size(); ++k) {
      const std::vector<Rational> xy = read_numbers(domain[k], 2, index("domain", k), "a vertex [x, y]");
      v.push_back(Point{xy[0], xy[1]});
    }
    require_simple_counter_clockwise(v);
    return v;
  }

  // Edge k runs from v[k] to v[k+1 mod m]. In order: no edge of length zero; adjacent edges meet
  // only at their common vertex (for non-degenerate edges, this fails exactly when the boundary
  // folds back on itself); non-adjacent edges do not meet; the signed area is positive (a simple
  // polygon has non-zero area).
  void require_simple_counter_clockwise(const std::vector<Point>& v) const {
    const std::size_t m = v.size();
    const auto vertex = [](std::size_t k) { return index("domain", k); };
    const auto edge = [&](std::size_t k) {
      return "edge " + std::to_string(k) + " (" + vertex(k) + " to " + vertex((k + 1) % m) + ")";
    };
    for (std::size_t k = 0; k < m; ++k) {
      const Point &a = v[k], &b = v[(k + 1) % m];
      if (a.x == b.x && a.y == b.y)
        fail("domain", vertex(k) + " and " + vertex((k + 1) % m) + " are the same point " + show(a) + " (edge " +
                           std::to_string(k) + " has length zero)");
    }
    for (std::size_t k = 0; k < m; ++k) {
      const Point &a = v[(k + m - 1) % m], &b = v[k], &c = v[(k + 1) % m];
      if (orientation(a, b, c) == Sign::zero && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0)
        fail("domain", "the boundary folds back at " + vertex(k) + " " + show(b) + ": " + edge((k + m - 1) % m) +
                           " and " + edge(k) + " overlap");
    }
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 2; j < m; ++j) {
        if (i == 0 && j == m - 1) continue;  // adjacent through v[0]
        if (const std::optional<Meeting> meet = segments_meet(v[i], v[i + 1], v[j], v[(j + 1) % m]))
          fail("domain", edge(i) + " and " + edge(j) + (meet->crossing ? " cross" : " touch") + " at " +
                             show(meet->at) + "; the domain must be a simple polygon");
      }
    Rational twice_area = 0;
    for (std::size_t k = 0; k < m; ++k) twice_area += v[k].x * v[(k + 1) % m].y - v[(k + 1) % m].x * v[k].y;
    if (twice_area < 0) fail("domain", "the vertices are clockwise; list the vertices counter-clockwise");
  }

  static std::vector<Point> default_box(const std::vector<Point>& sites) {
    const auto [x_lo, x_hi] = std::minmax_element(sites.begin(), sites.end(),
                                                  [](const Point& p, const Point& q) { return p.x < q.x; });
    const auto [y_lo, y_hi] = std::minmax_element(sites.begin(), sites.end(),
                                                  [](const Point& p, const Point& q) { return p.y < q.y; });
    const Rational extent = std::max(x_hi->x - x_lo->x, y_hi->y - y_lo->y);
    const Rational margin = extent == 0 ? Rational(1) : extent / 8;
    const Rational x0 = x_lo->x - margin, x1 = x_hi->x + margin, y0 = y_lo->y - margin, y1 = y_hi->y + margin;
    return {Point{x0, y0}, Point{x1, y0}, Point{x1, y1}, Point{x0, y1}};
  }

  // Site indices: an array of `count` distinct indices from 0 to n − 1 at `path`.
  std::vector<int> read_indices(const Json& s, std::size_t count, std::size_t n, const std::string& path,
                                const char* what) const {
    if (!s.is_array() || s.size() != count) fail(path, std::string("expected ") + what + ", got " + show(s));
    std::vector<int> ends;
    for (std::size_t e = 0; e < count; ++e) {
      if (!s[e].is_number_unsigned() || s[e].get<std::uint64_t>() >= n)
        fail(index(path, e), "expected a site index from 0 to " + std::to_string(n - 1) + ", got " + show(s[e]));
      const int v = static_cast<int>(s[e].get<std::uint64_t>());
      if (std::find(ends.begin(), ends.end(), v) != ends.end()) fail(path, "repeats " + index("sites", v));
      ends.push_back(v);
    }
    return ends;
  }

  std::vector<std::array<int, 3>> read_triangles(const Json& triangles, std::size_t n) const {
    if (!triangles.is_array()) fail("triangles", "expected an array of site-index triples [i, j, k], got " + show(triangles));
    std::vector<std::array<int, 3>> result;
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      const std::vector<int> t = read_indices(triangles[k], 3, n, index("triangles", k), "[i, j, k] with three site indices");
      result.push_back({t[0], t[1], t[2]});
    }
    return result;
  }

  std::vector<std::pair<int, int>> read_segments(const Json& segments, std::size_t n) const {
    if (!segments.is_array()) fail("segments", "expected an array of site-index pairs [i, j], got " + show(segments));
    std::vector<std::pair<int, int>> result;
    std::map<std::pair<int, int>, std::size_t> first_of;  // {min, max} -> first segment joining them
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const std::string path = index("segments", k);
      const Json& s = segments[k];
      const std::vector<int> ends = read_indices(s, 2, n, path, "[i, j] with two site indices");
      const auto [it, is_new] = first_of.emplace(std::minmax(ends[0], ends[1]), k);
      if (!is_new)
        fail(path, "repeats " + index("segments", it->second) + " (" + index("sites", ends[0]) + " to " +
                       index("sites", ends[1]) + ")");
      result.emplace_back(ends[0], ends[1]);
    }
    return result;
  }

  std::string source_;
};

}  // namespace

SiteSet read_site_set(std::istream& in, const std::string& source_name) {
  ExactDocument document(source_name);
  Json::sax_parse(in, &document);  // throws InputError on malformed JSON
  return Reader(source_name).read(document.take());
}

std::vector<predicates::Point2<Rational>> read_domain_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  ExactDocument document(path);
  Json::sax_parse(in, &document);
  return Reader(path).read_domain_only(document.take());
}

SiteSet read_site_set_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  return read_site_set(in, path);
}

}  // namespace anisocert::io
