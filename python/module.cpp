// `_anisocert`: the native half of the Python module (docs/python.md; the Python half,
// anisocert/__init__.py, checks shapes and dtypes and turns every number into an exact token).
// Numbers arrive as a float64 array (each double the rational it is) or as rows of exact texts
// (integers, decimals, fractions p/q: parse_input_number, as every reader of the CLI), so nothing
// passes through a lossy conversion. The checks are the C++ API's (api/anisocert.hpp), so the
// reports are `anisocert certify --json`'s. Long calls run on a worker thread with the GIL
// released; the caller's thread relays progress lines and checks for Ctrl-C every 0.1 s (on
// KeyboardInterrupt the worker stops at its next progress line, or, the certifier having none,
// finishes on its own copy of the input, its result unused).
#include "api/anisocert.hpp"
#include "geometry/boundary_polygon.hpp"
#include "geometry/builtin_polyhedra.hpp"
#include "geometry/polygon.hpp"
#include "io/diagram_json.hpp"
#include "io/field_source.hpp"
#include "io/formats/polyhedron_file.hpp"
#include "io/mesh_json.hpp"
#include "io/reports/certify_report.hpp"
#include "io/reports/dual_report.hpp"
#include "io/svg/certify_svg.hpp"
#include "io/svg/diagram_svg.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "refiners/registry.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace py = pybind11;

namespace anisocert::python {
namespace {

std::string at(const std::string& what, std::size_t i, std::size_t j) {
  return what + "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
}

// A rows × cols matrix of exact numbers: a C-contiguous float64 array, or a list of rows of texts.
struct Numbers {
  std::size_t rows = 0, cols = 0;
  std::vector<Rational> v;
  const Rational& operator()(std::size_t i, std::size_t j) const { return v[i * cols + j]; }
};

Numbers exact_numbers(const py::handle& o, const std::string& what, std::size_t cols) {
  Numbers n;
  n.cols = cols;
  if (py::isinstance<py::array>(o)) {
    const auto a = py::array_t<double, py::array::c_style>::ensure(o);
    if (!a || a.ndim() != 2 || static_cast<std::size_t>(a.shape(1)) != cols)
      throw std::invalid_argument(what + ": expected a float64 array of shape (n, " + std::to_string(cols) + ")");
    n.rows = static_cast<std::size_t>(a.shape(0));
    const double* d = a.data();
    n.v.reserve(n.rows * cols);
    for (std::size_t i = 0; i < n.rows; ++i)
      for (std::size_t j = 0; j < cols; ++j) {
        try {
          n.v.push_back(rational_from_double(d[i * cols + j]));
        } catch (const NumberSyntaxError& e) {
          throw std::invalid_argument(at(what, i, j) + ": " + e.what());
        }
      }
    return n;
  }
  const auto rows = o.cast<std::vector<std::vector<std::string>>>();
  n.rows = rows.size();
  n.v.reserve(n.rows * cols);
  for (std::size_t i = 0; i < n.rows; ++i) {
    if (rows[i].size() != cols)
      throw std::invalid_argument(what + "[" + std::to_string(i) + "]: " + std::to_string(rows[i].size()) + " numbers, expected " + std::to_string(cols));
    for (std::size_t j = 0; j < cols; ++j) {
      try {
        n.v.push_back(parse_input_number(rows[i][j]));
      } catch (const NumberSyntaxError& e) {
        throw std::invalid_argument(at(what, i, j) + ": " + e.what());
      }
    }
  }
  return n;
}

// Rows of K indices from an int64 array of shape (m, K).
template <std::size_t K>
std::vector<std::array<int, K>> index_rows(const py::handle& o, const std::string& what) {
  const auto a = py::array_t<std::int64_t, py::array::c_style>::ensure(o);
  if (!a || a.ndim() != 2 || static_cast<std::size_t>(a.shape(1)) != K)
    throw std::invalid_argument(what + ": expected an integer array of shape (m, " + std::to_string(K) + ")");
  std::vector<std::array<int, K>> rows(static_cast<std::size_t>(a.shape(0)));
  const std::int64_t* d = a.data();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < K; ++j) {
      const std::int64_t x = d[i * K + j];
      if (x < 0 || x > std::numeric_limits<int>::max())
        throw std::invalid_argument(at(what, i, j) + ": index " + std::to_string(x) + " out of range");
      rows[i][j] = static_cast<int>(x);
    }
  return rows;
}

// A field's parameters, name=value (the CLI's --param).
std::vector<std::string> param_texts(const py::dict& params) {
  std::vector<std::string> t;
  for (const auto& [k, v] : params) t.push_back(k.cast<std::string>() + "=" + v.cast<std::string>());
  return t;
}

// The options dictionary the Python layer builds (checks, a list; bounds as exact texts;
// all_witnesses; threads) as the oracle's CertifyOptions or Certify3Options.
template <class O>
O options_from(const py::dict& d) {
  O o;
  o.metric = true;  // the CLI's default checks: valid, uniform, metric
  const auto number = [&](const char* key) -> std::optional<Rational> {
    if (!d.contains(key) || d[key].is_none()) return std::nullopt;
    try {
      return parse_input_number(d[key].cast<std::string>());
    } catch (const NumberSyntaxError& e) {
      throw std::invalid_argument(std::string(key) + ": " + e.what());
    }
  };
  if (d.contains("checks")) {
    o.valid = o.uniform = o.metric = false;
    for (const auto& k : d["checks"].cast<std::vector<std::string>>()) {
      if (k == "valid") o.valid = true;
      else if (k == "uniform") o.uniform = true;
      else if (k == "metric") o.metric = true;
      else throw std::invalid_argument("checks: unknown check \"" + k + "\" (valid, uniform, metric)");
    }
  }
  o.rho0 = number("rho0"), o.gamma0 = number("gamma0"), o.min_quality = number("min_quality"), o.min_angle = number("min_angle");
  const auto lo = number("length_lo"), hi = number("length_hi");
  if (lo.has_value() != hi.has_value()) throw std::invalid_argument("length_range: give both ends");
  if (lo) o.length_range = std::pair{*lo, *hi};
  const bool all = d.contains("all_witnesses") && d["all_witnesses"].cast<bool>();
  o.described_witnesses = all ? oracle::all_witnesses : oracle::default_described_witnesses;
  if (d.contains("threads")) o.threads = d["threads"].cast<int>();
  return o;
}

using Say = std::function<void(const std::string&)>;
struct Interrupted {};  // thrown by Say on the worker once the caller was interrupted

// Runs work(say) on a worker thread while this thread, GIL released, waits; every 0.1 s it
// takes the GIL to pass the lines said to `progress` and to check for signals (Ctrl-C).
template <class R>
R interruptible(std::function<R(const Say&)> work, const py::object& progress) {
  struct State {
    std::mutex m;
    std::condition_variable cv;
    std::deque<std::string> lines;
    std::atomic<bool> stop = false;  // set on an interrupt: the worker's next line ends it
    bool done = false;
    std::optional<R> result;
    std::exception_ptr error;
  };
  auto s = std::make_shared<State>();
  std::thread worker([s, work = std::move(work)] {
    try {
      auto result = work([s](const std::string& line) {
        if (s->stop) throw Interrupted{};
        std::lock_guard lock(s->m);
        s->lines.push_back(line);
        s->cv.notify_all();
      });
      std::lock_guard lock(s->m);
      s->result.emplace(std::move(result));
    } catch (const Interrupted&) {  // the caller has gone
    } catch (...) {
      std::lock_guard lock(s->m);
      s->error = std::current_exception();
    }
    std::lock_guard lock(s->m);
    s->done = true;
    s->cv.notify_all();
  });
  try {
    for (bool done = false; !done;) {
      std::deque<std::string> lines;
      {
        py::gil_scoped_release release;
        std::unique_lock lock(s->m);
        s->cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return s->done || !s->lines.empty(); });
        lines.swap(s->lines);
        done = s->done;
      }
      if (!progress.is_none())
        for (const auto& line : lines) progress(line);
      if (!done && PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  } catch (...) {
    s->stop = true;    // a refiner or the diagram stops at its next progress line; the certifier runs on
    worker.detach();  // it owns its input (captured by value) and its state (shared)
    throw;
  }
  worker.join();
  if (s->error) std::rethrow_exception(s->error);
  return std::move(*s->result);
}

// A certificate with the mesh it is about (for the picture).
template <class MeshT, class Report>
struct Result {
  MeshT mesh;
  CertificateOf<Report> certificate;
};
using Result2 = Result<Mesh, oracle::CertifyReport>;
using Result3 = Result<Mesh3, oracle::Certify3Report>;

// The meshes of the Python layer's arrays, with metrics given (rows of 3 or 6) or a field's at the
// vertices (the CLI's --field and --param), and the tetrahedral mesh's declared triangles.
Mesh triangle_mesh(const py::handle& points, const py::handle& triangles, const py::handle& metrics) {
  const Numbers x = exact_numbers(points, "points", 2);
  Mesh mesh;
  for (std::size_t i = 0; i < x.rows; ++i) mesh.sites.push_back({x(i, 0), x(i, 1)});
  mesh.triangles = index_rows<3>(triangles, "cells");
  if (!metrics.is_none()) {
    const Numbers m = exact_numbers(metrics, "metrics", 3);
    for (std::size_t i = 0; i < m.rows; ++i) mesh.metrics.push_back({m(i, 0), m(i, 1), m(i, 2)});
  }
  return mesh;
}

// A field's metrics at the vertices, when one is named (on the worker: a background mesh is read
// and searched there).
void apply_field(Mesh& mesh, const std::string& field, const std::vector<std::string>& params) {
  if (!field.empty()) mesh.metrics = io::metrics_at(io::field_source(field, params), field, mesh.sites);
}
void apply_field(Mesh3& mesh, const std::string& field, const std::vector<std::string>& params) {
  if (!field.empty()) mesh.metrics = io::metrics3_at(field, params, mesh.vertices);
}

// What the report says the metrics came from: the CLI's "--field NAME", or nothing (given).
std::string source_of(const std::string& field) { return field.empty() ? "" : "--field " + field; }

Mesh3 tetrahedral_mesh(const py::handle& points, const py::handle& tetrahedra, const py::handle& metrics, const py::handle& triangles) {
  const Numbers x = exact_numbers(points, "points", 3);
  Mesh3 mesh;
  for (std::size_t i = 0; i < x.rows; ++i) mesh.vertices.push_back({x(i, 0), x(i, 1), x(i, 2)});
  mesh.tetrahedra = index_rows<4>(tetrahedra, "cells");
  if (!triangles.is_none()) mesh.triangles = index_rows<3>(triangles, "triangles");
  if (!metrics.is_none()) {
    const Numbers m = exact_numbers(metrics, "metrics", 6);
    for (std::size_t i = 0; i < m.rows; ++i) mesh.metrics.push_back({m(i, 0), m(i, 1), m(i, 2), m(i, 3), m(i, 4), m(i, 5)});
  }
  return mesh;
}

// The API's certificate of mesh, interruptibly; `cells` names its cells in the progress line.
template <class R, class MeshT, class O>
R certified(MeshT mesh, const O& o, const std::string& field, const py::dict& params, std::size_t count, const char* cells,
            const py::object& progress) {
  return interruptible<R>(
      [mesh = std::move(mesh), o, field, params = param_texts(params), count, cells](const auto& say) mutable {
        apply_field(mesh, field, params);
        say("certifying " + std::to_string(count) + " " + cells);
        R r{mesh, certify(mesh, {}, o)};
        r.certificate.verdict.metric_source = source_of(field);
        say("done");
        return r;
      },
      progress);
}

Result2 certify2(const py::handle& points, const py::handle& triangles, const py::handle& metrics, const py::handle& edges,
                 const py::handle& domain, const py::handle& segments, const std::string& field, const py::dict& params,
                 const py::dict& options, const py::object& progress) {
  const auto o = options_from<CertifyOptions>(options);
  Mesh mesh = triangle_mesh(points, triangles, metrics);
  if (!edges.is_none())
    for (const auto& e : index_rows<2>(edges, "edges")) mesh.edges.push_back({e[0], e[1]});
  if (!segments.is_none())
    for (const auto& e : index_rows<2>(segments, "segments")) mesh.segments.push_back({e[0], e[1]});
  if (!domain.is_none()) {
    const Numbers c = exact_numbers(domain, "domain", 2);
    for (std::size_t i = 0; i < c.rows; ++i) mesh.domain.push_back({c(i, 0), c(i, 1)});
  }
  const std::size_t count = mesh.triangles.size();
  return certified<Result2>(std::move(mesh), o, field, params, count, "triangles", progress);
}

Result3 certify3(const py::handle& points, const py::handle& tetrahedra, const py::handle& metrics, const py::handle& triangles,
                 const std::string& field, const py::dict& params, const py::dict& options, const py::object& progress) {
  const auto o = options_from<Certify3Options>(options);
  Mesh3 mesh = tetrahedral_mesh(points, tetrahedra, metrics, triangles);
  const std::size_t count = mesh.tetrahedra.size();
  return certified<Result3>(std::move(mesh), o, field, params, count, "tetrahedra", progress);
}

// Exact numbers back to Python: a float64 array when every one is a double, else rows of
// exact texts (the Python layer makes Fractions of them).
py::object to_python(const std::vector<std::vector<Rational>>& rows, std::size_t cols) {
  bool doubles = true;
  std::vector<double> d;
  d.reserve(rows.size() * cols);
  for (const auto& r : rows)
    for (const auto& q : r) {
      const double x = q.convert_to<double>();  // ±∞ beyond the doubles (a file may hold 1e310)
      doubles = doubles && std::isfinite(x) && Rational(x) == q;
      d.push_back(x);
    }
  if (doubles) {
    py::array_t<double> a({rows.size(), cols});
    std::copy(d.begin(), d.end(), a.mutable_data());
    return a;
  }
  py::list out;
  for (const auto& r : rows) {
    py::list row;
    for (const auto& q : r) row.append(to_exact_string(q));
    out.append(row);
  }
  return out;
}

template <std::size_t K>
py::array_t<std::int64_t> to_python(const std::vector<std::array<int, K>>& rows) {
  py::array_t<std::int64_t> a({rows.size(), K});
  auto* d = a.mutable_data();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < K; ++j) d[i * K + j] = rows[i][j];
  return a;
}

// A mesh's arrays for the Python layer: points, cells, metrics (None when there are none), and
// the triangle mesh's declared edges, segments and domain polygon, or the tetrahedral mesh's
// declared triangles.
py::dict to_python(const Mesh3& m) {
  std::vector<std::vector<Rational>> p, g;
  for (const auto& v : m.vertices) p.push_back({v.x, v.y, v.z});
  for (const auto& s : m.metrics) g.push_back({s.m11, s.m12, s.m13, s.m22, s.m23, s.m33});
  py::dict d;
  d["dimension"] = 3;
  d["points"] = to_python(p, 3), d["cells"] = to_python(m.tetrahedra), d["triangles"] = to_python(m.triangles);
  d["metrics"] = m.metrics.empty() ? py::object(py::none()) : to_python(g, 6);
  return d;
}

py::dict to_python(const Mesh& m) {
  std::vector<std::vector<Rational>> p, g, corners;
  for (const auto& v : m.sites) p.push_back({v.x, v.y});
  for (const auto& s : m.metrics) g.push_back({s.m11, s.m12, s.m22});
  for (const auto& c : m.domain) corners.push_back({c.x, c.y});
  std::vector<std::array<int, 2>> edges, segments;
  for (const auto& e : m.edges) edges.push_back({e.first, e.second});
  for (const auto& e : m.segments) segments.push_back({e.first, e.second});
  py::dict d;
  d["dimension"] = 2;
  d["points"] = to_python(p, 2), d["cells"] = to_python(m.triangles), d["edges"] = to_python(edges);
  d["segments"] = to_python(segments);
  d["domain"] = m.domain.empty() ? py::object(py::none()) : to_python(corners, 2);
  d["metrics"] = m.metrics.empty() ? py::object(py::none()) : to_python(g, 3);
  return d;
}

py::dict read_file(const std::string& path, const std::string& metric, const std::string& format, const py::object& progress) {
  const MeshFile f = interruptible<MeshFile>([path, metric, format](const Say&) { return read_mesh(path, metric, format); }, progress);
  py::dict d = f.dimension == 3 ? to_python(f.mesh3) : to_python(f.mesh);
  d["metric_source"] = f.metric_source;
  return d;
}

// The C++ API's checks of a triangle mesh's input (indices naming sites, one positive definite
// metric per site, a simple counter-clockwise domain), each failure one line; nothing certified.
void check_input(const Mesh& mesh) {
  CertifyOptions none;
  none.valid = none.uniform = none.metric = false;
  (void)certify(mesh, {}, none);
}

// `anisocert dual`: is the mesh the dual of the exact D|Ω of its vertices (Ω the boundary of its
// triangles)? The diagram's progress lines go to `progress`.
struct DualResult {
  Mesh mesh;
  oracle::Diagram diagram;
  oracle::MeshDual dual;
  std::string metric_source;  // "--field NAME", or "" (the metrics given)
};

DualResult dual(const py::handle& points, const py::handle& triangles, const py::handle& metrics, const std::string& field,
                const py::dict& params, bool exact_only, int threads, const std::string& name, const py::object& progress) {
  Mesh mesh = triangle_mesh(points, triangles, metrics);
  if (mesh.triangles.empty()) throw std::invalid_argument(name + ": the mesh has no triangles");
  if (mesh.metrics.empty() && field.empty())
    throw std::invalid_argument(name + ": has no metric, which the diagram needs (give metrics or field)");
  oracle::DiagramOptions o;
  o.exact_only = exact_only, o.threads = threads;
  return interruptible<DualResult>(
      [mesh = std::move(mesh), o, name, field, params = param_texts(params)](const auto& say) mutable {
        apply_field(mesh, field, params);
        check_input(mesh);
        Mesh sites;
        sites.sites = mesh.sites, sites.metrics = mesh.metrics;
        try {
          sites.domain = geometry::boundary_polygon(mesh);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(name + ": " + e.what());
        }
        const std::string source = source_of(field);
        o.progress = say;
        try {
          oracle::Diagram d = oracle::compute_diagram(sites, o);
          oracle::MeshDual m = oracle::compare_with_dual(d, mesh.triangles, 100);
          return DualResult{mesh, std::move(d), std::move(m), source};
        } catch (const std::domain_error& e) {
          throw std::invalid_argument(name + ": " + e.what());
        }
      },
      progress);
}

// `anisocert diagram`: the exact D|Ω of sites with metrics, Ω a simple polygon.
oracle::Diagram diagram(const py::handle& sites, const py::handle& metrics, const py::handle& domain, bool exact_only, int threads,
                        const std::string& name, const py::object& progress) {
  const Numbers x = exact_numbers(sites, "sites", 2), m = exact_numbers(metrics, "metrics", 3), c = exact_numbers(domain, "domain", 2);
  Mesh in;
  for (std::size_t i = 0; i < x.rows; ++i) in.sites.push_back({x(i, 0), x(i, 1)});
  for (std::size_t i = 0; i < m.rows; ++i) in.metrics.push_back({m(i, 0), m(i, 1), m(i, 2)});
  for (std::size_t i = 0; i < c.rows; ++i) in.domain.push_back({c(i, 0), c(i, 1)});
  if (in.sites.empty()) throw std::invalid_argument("sites: none (the diagram needs at least one)");
  if (const auto pair = io::coincident_sites(in.sites))
    throw std::invalid_argument("sites[" + std::to_string(pair->first) + "] and sites[" + std::to_string(pair->second) +
                                "] coincide at " + geometry::point_excerpt(in.sites[pair->first]));
  check_input(in);
  oracle::DiagramOptions o;
  o.exact_only = exact_only, o.threads = threads;
  return interruptible<oracle::Diagram>(
      [in = std::move(in), o, name](const auto& say) mutable {
        o.progress = say;
        try {
          return oracle::compute_diagram(in, o);
        } catch (const std::domain_error& e) {
          throw std::invalid_argument(name + ": " + e.what());
        }
      },
      progress);
}

// A refiner's run, interruptibly, its refusals as one line: the domain's (after `where`), the
// field's, a parameter's.
template <class R>
R refiner_run(std::function<R(const Say&)> run, const std::string& where, const py::object& progress) {
  return interruptible<R>(
      [run = std::move(run), where](const Say& say) {
        try {
          return run(say);
        } catch (const refiners::common::DomainError& e) {
          throw std::invalid_argument(where + e.what());
        } catch (const refiners::common::FieldError& e) {
          throw std::invalid_argument(std::string("field: ") + e.what());
        } catch (const refiners::ParameterError& e) {
          throw std::invalid_argument(e.what());
        }
      },
      progress);
}

// `anisocert refine`: a refiner's run on a 2D domain ("square", a JSON domain file, or a polygon's
// corners) or a 3D one (cube, cube-cylinder, a surface file); 3D runs certified as the CLI does.
// Returns the mesh in doubles (the refiner's), the run's report lines, and for 3D the certificate.
py::dict refine(const py::object& domain, const std::string& algo, const std::string& field, const py::dict& params,
                const py::dict& parameters, const std::string& max_vertices, const std::string& max_seconds, unsigned seed,
                const py::object& progress) {
  const refiners::RefinerEntry* entry = refiners::find_refiner(algo);
  if (!entry) {
    std::string names;
    for (const auto& n : refiners::refiner_names()) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument("algo: unknown refiner \"" + algo + "\" (" + names + ")");
  }
  refiners::ParameterValues values = entry->defaults();
  for (const auto& [k, v] : parameters) {
    const std::string key = k.cast<std::string>();
    if (!values.count(key)) {
      std::string names;
      for (const auto& p : entry->parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw std::invalid_argument("parameter \"" + key + "\": not one of --algo " + algo + "'s (" + names + ")");
    }
    values[key] = io::option_double(key, v.cast<std::string>());
    const auto spec = std::find_if(entry->parameters.begin(), entry->parameters.end(), [&](const auto& p) { return p.name == key; });
    if (spec->flag && values[key] != 0 && values[key] != 1) throw std::invalid_argument("parameter \"" + key + "\": a flag, True or False");
  }
  refiners::common::Budget budget;
  if (!max_vertices.empty()) {
    const Rational v = parse_input_number(max_vertices);
    if (v < 1 || denominator(v) != 1 || v > Rational(std::numeric_limits<long>::max()))
      throw std::invalid_argument("max_vertices " + max_vertices + ": expected a positive whole number");
    budget.max_vertices = v.convert_to<std::size_t>();
  }
  if (!max_seconds.empty()) {
    budget.max_seconds = io::option_double("max_seconds", max_seconds);
    if (!(budget.max_seconds > 0)) throw std::invalid_argument("max_seconds " + max_seconds + ": expected a positive number");
  }
  const bool named = py::isinstance<py::str>(domain);
  const std::string text = named ? domain.cast<std::string>() : "";
  if (named && io::names_polyhedron(text)) {
    if (!entry->run3) throw std::invalid_argument("algo " + algo + " meshes polygons only: algo star meshes a 3D domain");
    const geometry::Polyhedron polyhedron = geometry::builtin_polyhedron(text) ? *geometry::builtin_polyhedron(text) : io::read_polyhedron_file(text);
    const std::string field_name = field.empty() ? "ugawg-linear" : field;
    const fields::MetricField3 f = io::field3_source(field_name, param_texts(params));
    const auto run = refiner_run<refiners::Run3>(
        [entry, polyhedron, f, values, budget, seed](const Say& say) {
          return entry->run3(refiners::common::Domain3(polyhedron), f, values, budget, seed, say);
        },
        text + ": ", progress);
    const Mesh3 exact = exact_mesh(run.result.mesh);
    py::dict out = to_python(exact);
    out["certificate"] = interruptible<Result3>(
        [exact, rho0 = values.at("rho0"), gamma0 = values.at("gamma0"), field_name](const Say&) {
          io::RunCertificate3 c = io::certify_run3(exact, rho0, gamma0, 0, "--field " + field_name);
          const bool holds = c.verdict.holds;
          return Result3{exact, Certificate3{holds, std::move(c.report), std::move(c.verdict)}};
        },
        progress);
    out["consistent"] = run.result.consistent, out["stop_reason"] = run.result.stop_reason, out["lines"] = run.report;
    return out;
  }
  io::DomainFile input{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, {}};
  if (named && text != "square") {
    if (text.find_first_of("./") == std::string::npos)
      throw std::invalid_argument("domain \"" + text + "\": no such built-in domain (square; in 3D: cube, cube-cylinder) and not a file name");
    input = io::read_domain_file(text);
  } else if (!named) {
    const Numbers c = exact_numbers(domain, "domain", 2);
    input.corners.clear();
    for (std::size_t i = 0; i < c.rows; ++i) input.corners.push_back({c(i, 0), c(i, 1)});
  }
  const fields::MetricField f = io::field_source(field.empty() ? "shock" : field, param_texts(params)).field;
  const std::string where = named ? text + ": " : "domain: ";
  const auto run = refiner_run<refiners::Run>(
      [entry, input, f, values, budget, seed](const Say& say) {
        return entry->run(refiners::common::Domain::from_exact(input.corners, input.points, input.interior_segments), f, values,
                          budget, seed, say);
      },
      where, progress);
  Mesh exact = geometry::exact(run.result.mesh);
  exact.edges = exact.segments;  // the boundary subsegments, as `anisocert refine -o` declares them
  py::dict out = to_python(exact);
  out["consistent"] = run.result.consistent, out["stop_reason"] = run.result.stop_reason, out["lines"] = run.report;
  return out;
}

}  // namespace
}  // namespace anisocert::python

namespace anisocert::python {
namespace {
// A certificate's Python face: holds, json(), text(name), svg(caption).
template <class R>
void bind_certificate(py::module_& m, const char* name) {
  py::class_<R>(m, name)
      .def_property_readonly("holds", [](const R& r) { return r.certificate.holds; })
      .def("json", [](const R& r) { return r.certificate.json(); })
      .def("text", [](const R& r, const std::string& title) { return r.certificate.text(title); })
      .def("svg", [](const R& r, const std::string& caption) { return io::certify_svg(r.mesh, r.certificate.report, caption); });
}
}  // namespace
}  // namespace anisocert::python

PYBIND11_MODULE(_anisocert, m) {
  using namespace anisocert;
  using namespace anisocert::python;
  m.doc() = "anisocert's native functions; use the package `anisocert` (docs/python.md)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bind_certificate<Result2>(m, "Certificate2");
  bind_certificate<Result3>(m, "Certificate3");
  py::class_<DualResult>(m, "Dual")
      .def_property_readonly("is_dual", [](const DualResult& r) { return r.dual.is_dual(); })
      .def_property_readonly("theorem7_disagreement", [](const DualResult& r) { return r.diagram.theorem7.disagreement; })
      .def("json", [](const DualResult& r) { return io::dual_json(r.diagram, r.dual, r.metric_source).dump(); })
      .def("text", [](const DualResult& r, const std::string& name) {
        return io::dual_text(r.diagram, r.dual, name, r.metric_source.empty() ? "the metrics given" : r.metric_source);
      })
      .def("svg", [](const DualResult& r, const std::string& caption) { return io::dual_svg(r.mesh, r.diagram, r.dual, caption); });
  py::class_<oracle::Diagram>(m, "Diagram")
      .def_property_readonly("theorem7_disagreement", [](const oracle::Diagram& d) { return d.theorem7.disagreement; })
      .def("json", [](const oracle::Diagram& d) { return io::diagram_json(d).dump(); })
      .def("svg", [](const oracle::Diagram& d) { return io::diagram_svg(d); });
  m.def("certify2", &certify2);
  m.def("certify3", &certify3);
  m.def("read", &read_file);
  m.def("dual", &dual);
  m.def("diagram", &diagram);
  m.def("refine", &refine);
}
