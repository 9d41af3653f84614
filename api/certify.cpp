// The installable API (api/anisocert.hpp): the certifier's input checked once here, where a
// reader's checks do not stand between a caller and oracle::certify_mesh; files through
// io/formats/registry.hpp.
#include "api/anisocert.hpp"

#include "geometry/polygon.hpp"
#include "io/formats/registry.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace anisocert {
namespace {

std::string indexed(const char* what, std::size_t i) { return std::string(what) + "[" + std::to_string(i) + "]"; }

std::string entries(const Metric& m) {
  return "[" + to_exact_string(m.m11) + ", " + to_exact_string(m.m12) + ", " + to_exact_string(m.m22) +
         "] is not positive definite (m11 > 0 and m11 m22 - m12^2 > 0)";
}
std::string entries(const Metric3& m) {
  return "[" + to_exact_string(m.m11) + ", " + to_exact_string(m.m12) + ", " + to_exact_string(m.m13) + ", " +
         to_exact_string(m.m22) + ", " + to_exact_string(m.m23) + ", " + to_exact_string(m.m33) +
         "] is not positive definite (its three leading minors must be positive)";
}

template <class M>
void check_metrics(const std::vector<M>& metrics, std::size_t sites, const char* what) {
  if (metrics.size() != sites)
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(metrics.size()) + " metrics for " +
                                std::to_string(sites) + " sites (one per site)");
  for (std::size_t i = 0; i < metrics.size(); ++i)
    if (!predicates::positive_definite(metrics[i])) throw std::invalid_argument(indexed(what, i) + ": the metric " + entries(metrics[i]));
}

void check_index(int v, std::size_t sites, const std::string& where) {
  if (v < 0 || static_cast<std::size_t>(v) >= sites)
    throw std::invalid_argument(where + ": site " + std::to_string(v) + " does not exist (" + std::to_string(sites) +
                                " sites)");
}

void check_pairs(const std::vector<std::pair<int, int>>& pairs, std::size_t sites, const char* what) {
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    check_index(pairs[i].first, sites, indexed(what, i));
    check_index(pairs[i].second, sites, indexed(what, i));
  }
}

// What certify_mesh takes on trust: indices naming sites, a simple counter-clockwise domain.
void check_mesh(const Mesh& mesh) {
  const std::size_t n = mesh.sites.size();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t]) check_index(v, n, indexed("triangles", t));
  check_pairs(mesh.segments, n, "segments");
  check_pairs(mesh.edges, n, "edges");
  if (!mesh.domain.empty()) {
    if (mesh.domain.size() < 3)
      throw std::invalid_argument("domain: " + std::to_string(mesh.domain.size()) + " corners (at least 3, or none)");
    if (const auto defect = geometry::simplicity_defect(mesh.domain))
      throw std::invalid_argument("domain: " + geometry::describe(*defect, mesh.domain, "domain"));
  }
}

// The bounds' texts for the report, each bound checked in its range; `type` names the options
// struct in messages (CertifyOptions, Certify3Options: the same bounds).
template <class O>
io::BoundTexts bound_texts(const O& o, const char* type) {
  const auto fail = [type](const std::string& what) { throw std::invalid_argument(std::string(type) + ": " + what); };
  io::BoundTexts b;
  if (o.rho0) {
    if (*o.rho0 <= 0) fail("rho0 must be positive");
    b.rho0 = to_exact_string(*o.rho0);
  }
  if (o.gamma0) {
    if (*o.gamma0 < 1) fail("gamma0 must be at least 1");
    b.gamma0 = to_exact_string(*o.gamma0);
  }
  if (o.length_range) {
    if (o.length_range->first < 0 || o.length_range->first > o.length_range->second)
      fail("length_range: expected 0 <= low <= high");
    b.length_lo = to_exact_string(o.length_range->first), b.length_hi = to_exact_string(o.length_range->second);
  }
  if (o.min_quality) {
    if (*o.min_quality < 0 || *o.min_quality > 1) fail("min_quality must be in [0, 1]");
    b.min_quality = to_exact_string(*o.min_quality);
  }
  if (o.min_angle) {
    if (*o.min_angle <= 0 || *o.min_angle > 90) fail("min_angle must be in (0, 90] degrees");
    b.min_angle = to_exact_string(*o.min_angle);
  }
  if ((o.length_range || o.min_quality || o.min_angle) && !o.metric)
    fail("length_range, min_quality and min_angle need the metric check (metric = true)");
  return b;
}

Rational exact_number(double x, const std::string& where) {
  try {
    return rational_from_double(x);
  } catch (const NumberSyntaxError& e) {
    throw std::invalid_argument(where + ": " + e.what());
  }
}

Point exact_point(const predicates::Point2<double>& p, const std::string& where) {
  return {exact_number(p.x, where + ".x"), exact_number(p.y, where + ".y")};
}

Point3 exact_point(const predicates::Point3<double>& p, const std::string& where) {
  return {exact_number(p.x, where + ".x"), exact_number(p.y, where + ".y"), exact_number(p.z, where + ".z")};
}

Metric exact_metric(const DoubleMetric& m, const std::string& where) {
  return {exact_number(m.m11, where + ".m11"), exact_number(m.m12, where + ".m12"), exact_number(m.m22, where + ".m22")};
}

Metric3 exact_metric(const DoubleMetric3& m, const std::string& where) {
  return {exact_number(m.m11, where + ".m11"), exact_number(m.m12, where + ".m12"), exact_number(m.m13, where + ".m13"),
          exact_number(m.m22, where + ".m22"), exact_number(m.m23, where + ".m23"), exact_number(m.m33, where + ".m33")};
}

template <class D>
auto exact_metrics(const std::vector<D>& metrics, const char* what) {
  std::vector<decltype(exact_metric(metrics.front(), ""))> e;
  e.reserve(metrics.size());
  for (std::size_t i = 0; i < metrics.size(); ++i) e.push_back(exact_metric(metrics[i], indexed(what, i)));
  return e;
}

// What certify_mesh3 takes on trust: indices naming vertices (the bounds: bound_texts).
void check_mesh(const Mesh3& mesh) {
  const std::size_t n = mesh.vertices.size();
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for (int v : mesh.tetrahedra[t]) check_index(v, n, indexed("tetrahedra", t));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t]) check_index(v, n, indexed("triangles", t));
}

}  // namespace

template <class Report>
std::string CertificateOf<Report>::text(const std::string& name) const {
  return io::full_text(verdict, name);
}

template <class Report>
std::string CertificateOf<Report>::json() const {
  std::ostringstream out;
  io::write_json(out, verdict, report);
  return out.str();
}

template struct CertificateOf<oracle::CertifyReport>;
template struct CertificateOf<oracle::Certify3Report>;

Certificate certify(const Mesh& mesh, const std::vector<Metric>& metrics, const CertifyOptions& options) {
  check_mesh(mesh);
  const io::BoundTexts bounds = bound_texts(options, "CertifyOptions");
  if (!metrics.empty()) check_metrics(metrics, mesh.sites.size(), "metrics");
  else if (!mesh.metrics.empty()) check_metrics(mesh.metrics, mesh.sites.size(), "mesh.metrics");
  Mesh with_metrics;
  if (!metrics.empty()) {
    with_metrics = mesh;
    with_metrics.metrics = metrics;
  }
  const Mesh& m = metrics.empty() ? mesh : with_metrics;
  Certificate c;
  c.report = oracle::certify_mesh(m, options);
  c.verdict = io::certify_verdict(c.report, options, m, bounds);
  c.holds = c.verdict.holds;
  return c;
}

Mesh exact_mesh(const DoubleMesh& mesh) {
  Mesh e;
  e.sites.reserve(mesh.sites.size());
  for (std::size_t i = 0; i < mesh.sites.size(); ++i) e.sites.push_back(exact_point(mesh.sites[i], indexed("sites", i)));
  e.metrics = exact_metrics(mesh.metrics, "mesh.metrics");
  for (std::size_t i = 0; i < mesh.domain.size(); ++i) e.domain.push_back(exact_point(mesh.domain[i], indexed("domain", i)));
  e.segments = mesh.segments, e.edges = mesh.edges, e.triangles = mesh.triangles;
  return e;
}

Certificate certify(const DoubleMesh& mesh, const std::vector<DoubleMetric>& metrics, const CertifyOptions& options) {
  return certify(exact_mesh(mesh), exact_metrics(metrics, "metrics"), options);
}

MeshFile read_mesh(const std::string& path, const std::string& metric_path, const std::string& format) {
  return io::read_mesh_file(path, format, {}, metric_path);
}

std::vector<std::string> write_mesh(const MeshFile& m, const std::string& path, const std::string& format) {
  const std::vector<io::FileText> files = io::mesh_format_to_write(path, format).write(m, path);
  // Every file complete under a temporary name first, then renamed: no file is left half-written.
  const auto partial = [](const io::FileText& f) { return f.path + ".partial"; };
  const auto fail = [&](std::size_t from, std::size_t to, const std::string& what) {
    for (std::size_t i = from; i < to; ++i) std::remove(partial(files[i]).c_str());
    throw std::runtime_error("cannot write " + what);
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::ofstream out(partial(files[i]), std::ios::binary | std::ios::trunc);
    out << files[i].content;
    out.flush();
    if (!out) fail(0, i + 1, files[i].path);
  }
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (std::rename(partial(files[i]).c_str(), files[i].path.c_str()) != 0) fail(i, files.size(), files[i].path);
    paths.push_back(files[i].path);
  }
  return paths;
}

std::vector<std::string> write_mesh(const Mesh& m, const std::string& path, const std::string& format) {
  MeshFile f;
  f.mesh = m;
  return write_mesh(f, path, format);
}

Certificate3 certify(const Mesh3& mesh, const std::vector<Metric3>& metrics, const Certify3Options& options) {
  check_mesh(mesh);
  const io::BoundTexts bounds = bound_texts(options, "Certify3Options");
  if (!metrics.empty()) check_metrics(metrics, mesh.vertices.size(), "metrics");
  else if (!mesh.metrics.empty()) check_metrics(mesh.metrics, mesh.vertices.size(), "mesh.metrics");
  Mesh3 with_metrics;
  if (!metrics.empty()) {
    with_metrics = mesh;
    with_metrics.metrics = metrics;
  }
  const Mesh3& m = metrics.empty() ? mesh : with_metrics;
  Certificate3 c;
  c.report = oracle::certify_mesh3(m, options);
  c.verdict = io::certify_verdict(c.report, options, m, bounds);
  c.holds = c.verdict.holds;
  return c;
}

Certificate3 certify(const DoubleMesh3& mesh, const std::vector<DoubleMetric3>& metrics, const Certify3Options& options) {
  return certify(exact_mesh(mesh), exact_metrics(metrics, "metrics"), options);
}

Mesh3 exact_mesh(const DoubleMesh3& mesh) {
  Mesh3 e;
  e.vertices.reserve(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) e.vertices.push_back(exact_point(mesh.vertices[i], indexed("vertices", i)));
  e.metrics = exact_metrics(mesh.metrics, "mesh.metrics");
  e.tetrahedra = mesh.tetrahedra, e.triangles = mesh.triangles;
  return e;
}

}  // namespace anisocert
