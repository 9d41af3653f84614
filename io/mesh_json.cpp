// Reads and validates the project's mesh file (mesh_json.hpp): numbers exact from their text,
// geometry checks exact (geometry/polygon.hpp), no tolerance.
#include "io/mesh_json.hpp"

#include "io/json/exact_document.hpp"
#include "io/input_file.hpp"
#include "io/json/schema_reader.hpp"
#include "predicates/metric.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

namespace anisocert::io {

// Sorted by (x, y), coincident sites are neighbours; ties keep index order.
std::optional<std::pair<std::size_t, std::size_t>> coincident_sites(const std::vector<predicates::Point2<Rational>>& sites) {
  std::vector<std::size_t> order(sites.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const auto &p = sites[i], &q = sites[j];
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : i < j;
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto &p = sites[order[k - 1]], &q = sites[order[k]];
    if (p.x == q.x && p.y == q.y) return std::pair{order[k - 1], order[k]};
  }
  return std::nullopt;
}

namespace {

using Json = nlohmann::json;
using Point = predicates::Point2<Rational>;
using geometry::Mesh;
using geometry::Polygon;

class MeshReader : SchemaReader {
 public:
  using SchemaReader::SchemaReader;

  // A domain file for the refiners: {"domain": [...]}, perhaps "points" and "interior_segments"
  // (other keys of the format allowed).
  DomainFile domain_only(const Json& doc) const {
    if (!doc.is_object()) fail("", "the top level must be an object, got " + show(doc));
    require_keys(doc, "", {"domain"}, {"sites", "domain", "segments", "edges", "triangles", "points", "interior_segments"});
    DomainFile d;
    d.corners = domain(doc.at("domain"));
    if (doc.contains("points")) {
      const Json& points = doc.at("points");
      if (!points.is_array()) fail("points", "expected an array of points [x, y], got " + show(points));
      for (std::size_t k = 0; k < points.size(); ++k) {
        const std::vector<Rational> xy = numbers(points[k], 2, indexed("points", k), "a point [x, y]");
        d.points.push_back(Point{xy[0], xy[1]});
      }
    }
    if (doc.contains("interior_segments")) {
      const std::size_t vertices = d.corners.size() + d.points.size();
      const Json& segments = doc.at("interior_segments");
      if (!segments.is_array()) fail("interior_segments", "expected an array of vertex-index pairs [i, j], got " + show(segments));
      for (std::size_t k = 0; k < segments.size(); ++k) {
        const std::vector<int> ends = indices(segments[k], 2, vertices, indexed("interior_segments", k),
                                              "[i, j] with two vertex indices (the corners, then the points)", true);
        d.interior_segments.emplace_back(ends[0], ends[1]);
      }
    }
    return d;
  }

  Mesh<Rational> mesh(const Json& doc) const {
    if (!doc.is_object()) fail("", "the top level must be an object, got " + show(doc));
    require_keys(doc, "", {"sites"}, {"sites", "domain", "segments", "edges", "triangles"});
    Mesh<Rational> m;
    sites(doc.at("sites"), m);
    require_distinct_sites(m.sites);
    if (doc.contains("domain")) {
      m.domain = domain(doc.at("domain"));
      for (std::size_t i = 0; i < m.sites.size(); ++i)
        if (!geometry::in_closed_polygon(m.sites[i], m.domain))
          fail("", indexed("sites", i) + " " + geometry::point_excerpt(m.sites[i]) + " lies outside the domain");
    } else if (!doc.contains("triangles")) {
      m.domain = default_box(m.sites);
    }
    if (doc.contains("segments")) m.segments = segments(doc.at("segments"), m.sites.size(), "segments");
    if (doc.contains("edges")) m.edges = segments(doc.at("edges"), m.sites.size(), "edges");
    if (doc.contains("triangles")) m.triangles = triangles(doc.at("triangles"), m.sites.size());
    return m;
  }

 private:
  void sites(const Json& sites, Mesh<Rational>& m) const {
    if (!sites.is_array() || sites.empty()) fail("sites", "expected a non-empty array of sites, got " + show(sites));
    for (std::size_t i = 0; i < sites.size(); ++i) {
      const std::string path = indexed("sites", i);
      const Json& site = sites[i];
      if (!site.is_object())
        fail(path, "expected an object {\"x\": ..., \"y\": ..., \"metric\": [m11, m12, m22]}, got " + show(site));
      require_keys(site, path, {"x", "y", "metric"}, {"x", "y", "metric"});
      m.sites.push_back(Point{number(site.at("x"), path + ".x"), number(site.at("y"), path + ".y")});
      const std::vector<Rational> e = numbers(site.at("metric"), 3, path + ".metric", "[m11, m12, m22]");
      try {
        m.metrics.push_back(predicates::Metric2(predicates::Sym2<Rational>{e[0], e[1], e[2]}).entries());
      } catch (const predicates::NotPositiveDefinite& err) {
        fail(path + ".metric", err.what());
      }
    }
  }

  void require_distinct_sites(const std::vector<Point>& sites) const {
    if (const auto pair = coincident_sites(sites))
      fail("", indexed("sites", pair->first) + " and " + indexed("sites", pair->second) + " coincide at " +
                   geometry::point_excerpt(sites[pair->first]));
  }

  Polygon<Rational> domain(const Json& domain) const {
    if (!domain.is_array() || domain.size() < 3)
      fail("domain", "expected an array of at least 3 vertices [x, y], got " + show(domain));
    Polygon<Rational> v;
    for (std::size_t k = 0; k < domain.size(); ++k) {
      const std::vector<Rational> xy = numbers(domain[k], 2, indexed("domain", k), "a vertex [x, y]");
      v.push_back(Point{xy[0], xy[1]});
    }
    if (const auto defect = geometry::simplicity_defect(v)) fail("domain", geometry::describe(*defect, v, "domain"));
    return v;
  }

  static Polygon<Rational> default_box(const std::vector<Point>& sites) {
    const auto [x_lo, x_hi] = std::minmax_element(sites.begin(), sites.end(),
                                                  [](const Point& p, const Point& q) { return p.x < q.x; });
    const auto [y_lo, y_hi] = std::minmax_element(sites.begin(), sites.end(),
                                                  [](const Point& p, const Point& q) { return p.y < q.y; });
    const Rational extent = std::max(x_hi->x - x_lo->x, y_hi->y - y_lo->y);
    const Rational margin = extent == 0 ? Rational(1) : extent / 8;
    const Rational x0 = x_lo->x - margin, x1 = x_hi->x + margin, y0 = y_lo->y - margin, y1 = y_hi->y + margin;
    return {Point{x0, y0}, Point{x1, y0}, Point{x1, y1}, Point{x0, y1}};
  }

  std::vector<std::array<int, 3>> triangles(const Json& triangles, std::size_t n) const {
    if (!triangles.is_array())
      fail("triangles", "expected an array of site-index triples [i, j, k], got " + show(triangles));
    std::vector<std::array<int, 3>> result;
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      const std::vector<int> t = indices(triangles[k], 3, n, indexed("triangles", k), "[i, j, k] with three site indices");
      result.push_back({t[0], t[1], t[2]});
    }
    return result;
  }

  std::vector<std::pair<int, int>> segments(const Json& segments, std::size_t n, const std::string& key) const {
    if (!segments.is_array()) fail(key, "expected an array of site-index pairs [i, j], got " + show(segments));
    std::vector<std::pair<int, int>> result;
    std::map<std::pair<int, int>, std::size_t> first_of;  // {min, max} -> first segment joining them
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const std::string path = indexed(key, k);
      const std::vector<int> ends = indices(segments[k], 2, n, path, "[i, j] with two site indices");
      const auto [it, is_new] = first_of.emplace(std::minmax(ends[0], ends[1]), k);
      if (!is_new)
        fail(path, "repeats " + indexed(key, it->second) + " (" + indexed("sites", ends[0]) + " to " +
                       indexed("sites", ends[1]) + ")");
      result.emplace_back(ends[0], ends[1]);
    }
    return result;
  }
};

Json parse_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return parse_exact_json(in, path);
}

// The rational a double denotes, as exact text in a JSON string.
std::string exact(const Rational& q) { return "\"" + to_exact_string(q) + "\""; }

}  // namespace

Mesh<Rational> read_mesh_json(std::istream& in, const std::string& source_name) {
  return MeshReader(source_name).mesh(parse_exact_json(in, source_name));
}

Mesh<Rational> read_mesh_json_file(const std::string& path) { return MeshReader(path).mesh(parse_file(path)); }

Mesh<Rational> read_triangle_mesh_file(const std::string& path) {
  Mesh<Rational> m = read_mesh_json_file(path);
  if (m.triangles.empty()) throw InputError(path + ": triangles: a mesh needs a non-empty \"triangles\" array");
  return m;
}

DomainFile read_domain_file(const std::string& path) { return MeshReader(path).domain_only(parse_file(path)); }

std::string mesh_json(const Mesh<Rational>& m) {
  if (m.metrics.size() != m.sites.size())
    throw InputError("the JSON mesh format needs a metric at every site (give one with --metric or --field)");
  std::ostringstream o;
  o << "{\"sites\": [\n";
  for (std::size_t i = 0; i < m.sites.size(); ++i)
    o << "  {\"x\": " << exact(m.sites[i].x) << ", \"y\": " << exact(m.sites[i].y) << ", \"metric\": ["
      << exact(m.metrics[i].m11) << ", " << exact(m.metrics[i].m12) << ", " << exact(m.metrics[i].m22) << "]}"
      << (i + 1 < m.sites.size() ? ",\n" : "\n");
  o << "]";
  if (!m.domain.empty()) {
    o << ",\n\"domain\": [";
    for (std::size_t i = 0; i < m.domain.size(); ++i) o << (i ? ", " : "") << "[" << exact(m.domain[i].x) << ", " << exact(m.domain[i].y) << "]";
    o << "]";
  }
  for (const auto& [key, list] : {std::pair{"segments", &m.segments}, std::pair{"edges", &m.edges}}) {
    if (list->empty()) continue;
    o << ",\n\"" << key << "\": [";
    for (std::size_t i = 0; i < list->size(); ++i) o << (i ? ", " : "") << "[" << (*list)[i].first << ", " << (*list)[i].second << "]";
    o << "]";
  }
  o << ",\n\"triangles\": [\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    o << "  [" << m.triangles[i][0] << ", " << m.triangles[i][1] << ", " << m.triangles[i][2] << "]"
      << (i + 1 < m.triangles.size() ? ",\n" : "\n");
  o << "]}\n";
  return o.str();
}

}  // namespace anisocert::io
