#include "cli/refine_from.hpp"

#include "cli/diagram_job.hpp"
#include "cli/output.hpp"
#include "cli/usage_error.hpp"
#include "fields/background.hpp"
#include "geometry/boundary_polygon.hpp"
#include "io/field_source.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "predicates/metric.hpp"
#include "predicates/orientation.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

namespace anisocert::cli {
namespace {

using predicates::Point2;

MeshMeasures measures(const geometry::Mesh<Rational>& mesh, const oracle::CertifyReport& r) {
  MeshMeasures m;
  m.vertices = mesh.sites.size(), m.triangles = mesh.triangles.size();
  if (r.lengths) m.edges = r.lengths->edges, m.unit_edges = r.lengths->unit_edges;
  if (r.angles) m.smallest_angle = r.angles->smallest;
  if (r.quality)
    for (const auto& [p, e] : r.quality->quantiles)
      if (p == 0.5) m.median_quality = (e.lo + e.hi) / 2;
  return m;
}

oracle::CertifyOptions measuring(bool uniform) {
  oracle::CertifyOptions o;
  o.valid = o.metric = true;
  o.uniform = uniform;
  o.described_witnesses = 1;
  return o;
}

std::string percent(std::size_t part, std::size_t whole) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f%%", whole == 0 ? 0.0 : 100.0 * double(part) / double(whole));
  return s;
}

std::string fixed(double x, int digits) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", digits, x);
  return s;
}

}  // namespace

StartingMesh starting_mesh(const MeshInput& in, bool exact_sites, bool quiet) {
  io::MeshFile file = read_mesh_input(in);
  if (file.dimension == 3)
    throw UsageError(in.path + " is a tetrahedral mesh: refine --from starts from triangle meshes (in 3D, --domain takes a surface)");
  const geometry::Mesh<Rational>& mesh = file.mesh;
  if (mesh.triangles.empty()) throw UsageError(in.path + ": the file has no triangles");
  if (mesh.metrics.empty()) throw UsageError(in.path + ": has no metric (give --metric FILE or --field NAME)");
  for (std::size_t k = 0; k < mesh.metrics.size(); ++k)
    if (!predicates::positive_definite(mesh.metrics[k]))
      throw UsageError(in.path + ": the metric at vertex " + std::to_string(k) + " " + geometry::point_excerpt(mesh.sites[k]) + " (" + file.metric_source +
                       ") is not positive definite");
  StartingMesh start;
  start.metric_source = in.field.empty() ? file.metric_source : "--field " + in.field;

  // The mesh as the certifier sees it: a valid triangulation, or bad input.
  const auto progress = progress_printer(quiet);
  if (progress) progress("refine --from: certifying " + in.path + " (" + std::to_string(mesh.triangles.size()) + " triangles)");
  const oracle::CertifyReport before = oracle::certify_mesh(mesh, measuring(false));
  if (!before.valid_holds()) {
    const std::string why = before.valid && !before.valid->failures.empty() ? before.valid->failures.front()
                            : !before.segment_failures.empty()              ? before.segment_failures.front()
                                                                            : "see anisocert certify";
    throw UsageError(in.path + " is not a valid triangulation: " + why);
  }
  start.before = measures(mesh, before);

  std::vector<int> loop;
  try {
    loop = geometry::boundary_loop(mesh);
  } catch (const std::invalid_argument& e) {
    throw UsageError(in.path + ": " + e.what());
  }
  start.boundary_vertices = loop.size();

  // Every coordinate as the nearest double, counted (or refused with --exact-sites).
  geometry::Mesh<Rational> rounded = mesh;
  std::vector<Point2<double>> doubles(mesh.sites.size());
  for (std::size_t k = 0; k < mesh.sites.size(); ++k) {
    const Point2<Rational>& p = mesh.sites[k];
    const Point2<double> q{p.x.convert_to<double>(), p.y.convert_to<double>()};
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) throw UsageError(in.path + ": vertex " + std::to_string(k) + " lies beyond the doubles' range");
    rounded.sites[k] = {Rational(q.x), Rational(q.y)};
    if (rounded.sites[k].x != p.x || rounded.sites[k].y != p.y) {
      if (exact_sites)
        throw UsageError(in.path + ": vertex " + std::to_string(k) + " " + geometry::point_excerpt(p) +
                         " is not a pair of doubles (--exact-sites; without it, it is rounded to the nearest)");
      ++start.rounded;
    }
    doubles[k] = q;
  }
  // The triangles counter-clockwise, and none flattened or flipped by the rounding.
  for (std::size_t t = 0; t < rounded.triangles.size(); ++t) {
    auto& tri = rounded.triangles[t];
    const Sign before_rounding = predicates::orientation(mesh.sites[tri[0]], mesh.sites[tri[1]], mesh.sites[tri[2]]);
    const Sign after = predicates::orientation(rounded.sites[tri[0]], rounded.sites[tri[1]], rounded.sites[tri[2]]);
    if (after != before_rounding)
      throw UsageError(in.path + ": rounding the vertices to doubles " + (after == Sign::zero ? "flattens" : "flips") + " triangle " +
                       std::to_string(t) + " (refine --from works in doubles)");
    if (after == Sign::negative) std::swap(tri[1], tri[2]);
  }

  if (!in.field.empty()) {
    try {
      start.field = io::field_source(in.field, in.params).field;
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
  } else {
    rounded.edges.clear(), rounded.segments.clear(), rounded.domain.clear();
    try {
      start.field = fields::background_field(std::make_shared<const fields::BackgroundMesh>(rounded), in.path);
    } catch (const fields::BackgroundMeshError& e) {
      throw UsageError(in.path + ": " + e.what());
    }
  }

  // Ω: the boundary loop, every vertex a corner; the other vertices are X's points; declared edges
  // that are not on the boundary are its interior segments.
  std::vector<int> index(mesh.sites.size(), -1);  // vertex → X's vertex
  geometry::Polygon<double> corners;
  for (int v : loop) index[static_cast<std::size_t>(v)] = static_cast<int>(corners.size()), corners.push_back(doubles[static_cast<std::size_t>(v)]);
  std::vector<Point2<double>> points;
  for (std::size_t k = 0; k < mesh.sites.size(); ++k)
    if (index[k] < 0) index[k] = static_cast<int>(corners.size() + points.size()), points.push_back(doubles[k]);
  std::set<std::pair<int, int>> boundary;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    boundary.insert({std::min(a, b), std::max(a, b)});
  }
  std::vector<std::pair<int, int>> segments;  // a file's declared edges, and a JSON mesh's constrained segments
  std::set<std::pair<int, int>> seen = boundary;
  for (const auto* list : {&mesh.edges, &mesh.segments})
    for (const auto& [a, b] : *list)
      if (a != b && seen.insert({std::min(a, b), std::max(a, b)}).second)
        segments.push_back({index[static_cast<std::size_t>(a)], index[static_cast<std::size_t>(b)]});
  start.interior_segments = segments.size();
  try {
    start.domain.emplace(corners, points, segments);
  } catch (const refiners::common::DomainError& e) {
    throw UsageError(in.path + ": " + e.what());
  }
  return start;
}

RefinedCertificate certify_refined(const refiners::RefinerEntry& entry, const geometry::Mesh<double>& m, bool quiet) {
  RefinedCertificate c;
  const geometry::Mesh<Rational> exact = geometry::exact(m);
  const auto progress = progress_printer(quiet);
  if (progress) progress("refine --from: certifying the output (" + std::to_string(exact.triangles.size()) + " triangles)");
  const oracle::CertifyReport r = oracle::certify_mesh(exact, measuring(!entry.dual_of_diagram));
  c.after = measures(exact, r);
  if (!r.valid_holds()) {
    c.line = "not certified: the output is no valid triangulation of Ω (" + std::to_string(r.valid ? r.valid->failure_count : 0) +
             " failures; anisocert certify says which)";
    return c;
  }
  if (!entry.dual_of_diagram) {
    c.holds = r.uniform_violations.empty();
    c.line = c.holds ? "certified: locally uniform (LU Definition 2.1: every triangle at v has an empty M_v-circumellipse), valid"
                     : "not certified: " + std::to_string(r.uniform_violations.count()) + " witnesses against local uniformity";
    return c;
  }
  // The oracle's D|Ω of the output's vertices, Ω the same set without its straight corners.
  geometry::Mesh<Rational> sites;
  sites.sites = exact.sites, sites.metrics = exact.metrics, sites.domain = geometry::without_straight_corners(exact.domain);
  DiagramOutputs options;
  options.quiet = quiet;
  options.progress_label = "refine --from: ";
  const oracle::Diagram d = exact_diagram(sites, "the output's vertices", options);
  const oracle::MeshDual dual = oracle::compare_with_dual(d, m.triangles, 0);
  c.holds = dual.is_dual() && d.dual_check.is_triangulation;
  c.line = c.holds ? "certified: the exact dual of D|Ω of its vertices, a triangulation of Ω (LS Theorem 7; decided by the oracle)"
                   : "not certified: " + std::to_string(dual.not_dual) + " triangles not dual and " + std::to_string(dual.missing_count) +
                         " dual triangles missing" + (d.dual_check.is_triangulation ? "" : "; the dual of D|Ω is no triangulation");
  return c;
}

std::string before_after_text(const StartingMesh& start, const RefinedCertificate& c, std::size_t vertices_in, std::size_t removed) {
  const MeshMeasures &b = start.before, &a = c.after;
  const std::size_t added = a.vertices + removed - vertices_in;
  const auto row = [](const std::string& name, const MeshMeasures& m) {
    return "  " + name + std::to_string(m.vertices) + " vertices, " + std::to_string(m.triangles) + " triangles, unit edges " +
           percent(m.unit_edges, m.edges) + " of " + std::to_string(m.edges) + ", smallest angle " + fixed(m.smallest_angle, 2) +
           "°, median quality " + fixed(m.median_quality, 3) + "\n";
  };
  return row("before: ", b) + row("after:  ", a) + "  vertices: " + std::to_string(vertices_in) + " in, " + std::to_string(added) + " added, " +
         std::to_string(removed) + " removed (" + fixed(double(a.vertices) / double(vertices_in), 3) + "×)\n  " + c.line + "\n";
}

}  // namespace anisocert::cli
