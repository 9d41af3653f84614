// `_anisocert`: the native half of the Python module (docs/python.md; the Python half,
// anisocert/__init__.py, checks shapes and dtypes and turns every number into an exact token).
// Numbers arrive as a float64 array (each double the rational it is) or as rows of exact texts
// (integers, decimals, fractions p/q: parse_input_number, as every reader of the CLI), so nothing
// passes through a lossy conversion. The checks are the C++ API's (api/anisocert.hpp), so the
// reports are `anisocert certify --json`'s. Long calls run on a worker thread with the GIL
// released; the caller's thread relays progress lines and checks for Ctrl-C every 0.1 s (on
// KeyboardInterrupt the worker is left to finish on its own copy of the input, its result unused).
#include "api/anisocert.hpp"
#include "io/svg/certify_svg.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
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

// The options dictionary the Python layer builds: checks (a list), bounds as exact texts,
// all_witnesses, threads.
struct Options {
  bool valid = true, uniform = true, metric = true, all_witnesses = false;
  std::optional<Rational> rho0, gamma0, min_quality, min_angle;
  std::optional<std::pair<Rational, Rational>> length_range;
  int threads = 0;
};

Options options_from(const py::dict& d) {
  Options o;
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
  if (lo && hi) o.length_range = std::pair{*lo, *hi};
  if (d.contains("all_witnesses")) o.all_witnesses = d["all_witnesses"].cast<bool>();
  if (d.contains("threads")) o.threads = d["threads"].cast<int>();
  return o;
}

template <class O>
O oracle_options(const Options& p) {
  O o;
  o.valid = p.valid, o.uniform = p.uniform, o.metric = p.metric;
  o.rho0 = p.rho0, o.gamma0 = p.gamma0, o.min_quality = p.min_quality, o.min_angle = p.min_angle, o.length_range = p.length_range;
  o.described_witnesses = p.all_witnesses ? oracle::all_witnesses : oracle::default_described_witnesses;
  o.threads = p.threads;
  return o;
}

// Runs work(say) on a worker thread while this thread, GIL released, waits; every 0.1 s it
// takes the GIL to pass the lines said to `progress` and to check for signals (Ctrl-C).
template <class R>
R interruptible(std::function<R(const std::function<void(const std::string&)>&)> work, const py::object& progress) {
  struct State {
    std::mutex m;
    std::condition_variable cv;
    std::deque<std::string> lines;
    bool done = false;
    std::optional<R> result;
    std::exception_ptr error;
  };
  auto s = std::make_shared<State>();
  std::thread worker([s, work = std::move(work)] {
    try {
      auto result = work([s](const std::string& line) {
        std::lock_guard lock(s->m);
        s->lines.push_back(line);
        s->cv.notify_all();
      });
      std::lock_guard lock(s->m);
      s->result.emplace(std::move(result));
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

Result2 certify2(const py::handle& points, const py::handle& triangles, const py::handle& metrics, const py::handle& edges,
                 const py::dict& options, const py::object& progress) {
  const Options p = options_from(options);
  const Numbers x = exact_numbers(points, "points", 2);
  Mesh mesh;
  for (std::size_t i = 0; i < x.rows; ++i) mesh.sites.push_back({x(i, 0), x(i, 1)});
  mesh.triangles = index_rows<3>(triangles, "cells");
  if (!edges.is_none())
    for (const auto& e : index_rows<2>(edges, "edges")) mesh.edges.push_back({e[0], e[1]});
  if (!metrics.is_none()) {
    const Numbers m = exact_numbers(metrics, "metrics", 3);
    for (std::size_t i = 0; i < m.rows; ++i) mesh.metrics.push_back({m(i, 0), m(i, 1), m(i, 2)});
  }
  const auto o = oracle_options<CertifyOptions>(p);
  return interruptible<Result2>(
      [mesh = std::move(mesh), o](const auto& say) {
        say("certifying " + std::to_string(mesh.triangles.size()) + " triangles");
        Result2 r{mesh, certify(mesh, {}, o)};
        say("done");
        return r;
      },
      progress);
}

Result3 certify3(const py::handle& points, const py::handle& tetrahedra, const py::handle& metrics, const py::handle& triangles,
                 const py::dict& options, const py::object& progress) {
  const Options p = options_from(options);
  const Numbers x = exact_numbers(points, "points", 3);
  Mesh3 mesh;
  for (std::size_t i = 0; i < x.rows; ++i) mesh.vertices.push_back({x(i, 0), x(i, 1), x(i, 2)});
  mesh.tetrahedra = index_rows<4>(tetrahedra, "cells");
  if (!triangles.is_none()) mesh.triangles = index_rows<3>(triangles, "triangles");
  if (!metrics.is_none()) {
    const Numbers m = exact_numbers(metrics, "metrics", 6);
    for (std::size_t i = 0; i < m.rows; ++i) mesh.metrics.push_back({m(i, 0), m(i, 1), m(i, 2), m(i, 3), m(i, 4), m(i, 5)});
  }
  const auto o = oracle_options<Certify3Options>(p);
  return interruptible<Result3>(
      [mesh = std::move(mesh), o](const auto& say) {
        say("certifying " + std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
        Result3 r{mesh, certify(mesh, {}, o)};
        say("done");
        return r;
      },
      progress);
}

// Exact numbers back to Python: a float64 array when every one is a double, else rows of
// exact texts (the Python layer makes Fractions of them).
py::object to_python(const std::vector<std::vector<Rational>>& rows, std::size_t cols) {
  bool doubles = true;
  std::vector<double> d;
  d.reserve(rows.size() * cols);
  for (const auto& r : rows)
    for (const auto& q : r) {
      const double x = q.convert_to<double>();
      doubles = doubles && Rational(x) == q;
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

py::dict read_file(const std::string& path, const std::string& metric, const std::string& format) {
  const MeshFile f = read_mesh(path, metric, format);
  py::dict d;
  d["dimension"] = f.dimension;
  d["metric_source"] = f.metric_source;
  if (f.dimension == 3) {
    const auto& m = f.mesh3;
    std::vector<std::vector<Rational>> p, g;
    for (const auto& v : m.vertices) p.push_back({v.x, v.y, v.z});
    for (const auto& s : m.metrics) g.push_back({s.m11, s.m12, s.m13, s.m22, s.m23, s.m33});
    d["points"] = to_python(p, 3), d["cells"] = to_python(m.tetrahedra), d["triangles"] = to_python(m.triangles);
    d["metrics"] = m.metrics.empty() ? py::object(py::none()) : to_python(g, 6);
  } else {
    const auto& m = f.mesh;
    std::vector<std::vector<Rational>> p, g;
    for (const auto& v : m.sites) p.push_back({v.x, v.y});
    for (const auto& s : m.metrics) g.push_back({s.m11, s.m12, s.m22});
    std::vector<std::array<int, 2>> edges;
    for (const auto& e : m.edges) edges.push_back({e.first, e.second});
    d["points"] = to_python(p, 2), d["cells"] = to_python(m.triangles), d["edges"] = to_python(edges);
    d["metrics"] = m.metrics.empty() ? py::object(py::none()) : to_python(g, 3);
  }
  return d;
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
  py::class_<Result2>(m, "Certificate2")
      .def_property_readonly("holds", [](const Result2& r) { return r.certificate.holds; })
      .def("json", [](const Result2& r) { return r.certificate.json(); })
      .def("text", [](const Result2& r, const std::string& name) { return r.certificate.text(name); })
      .def("svg", [](const Result2& r, const std::string& caption) { return io::certify_svg(r.mesh, r.certificate.report, caption); });
  py::class_<Result3>(m, "Certificate3")
      .def_property_readonly("holds", [](const Result3& r) { return r.certificate.holds; })
      .def("json", [](const Result3& r) { return r.certificate.json(); })
      .def("text", [](const Result3& r, const std::string& name) { return r.certificate.text(name); })
      .def("svg", [](const Result3& r, const std::string& caption) { return io::certify_svg(r.mesh, r.certificate.report, caption); });
  m.def("certify2", &certify2);
  m.def("certify3", &certify3);
  m.def("read", &read_file);
}
