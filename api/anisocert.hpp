#pragma once
// The installable C++ API (docs/api.md): the one header a mesher's own tests include, after
// `find_package(anisocert)` and linking `anisocert::anisocert`. It certifies a mesh exactly, as
// `anisocert certify` does (oracle/certify/mesh_certifier.hpp; tetrahedral meshes:
// mesh_certifier3.hpp), and reads and writes meshes in every format of io/formats/registry.hpp.
// Every number is exact: a double is taken as the rational it is.
//
//   anisocert::Certificate c = anisocert::certify(mesh, metrics);   // mesh in doubles or rationals
//   if (!c.holds) std::cerr << c.text("my mesh");                    // the witnesses, as the CLI prints them
//
// What throws: certify, std::invalid_argument for a mesh or metrics the certifier cannot take (the
// message names the index); read_mesh and write_mesh, anisocert::InputError for a bad file (one line
// naming the file, the place and what is wrong), std::runtime_error when a file cannot be written.
#include "geometry/mesh.hpp"
#include "geometry/mesh3.hpp"
#include "io/formats/mesh_file.hpp"
#include "io/input_error.hpp"
#include "io/reports/certify_report.hpp"
#include "numbers/rational.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/certify/mesh_certifier3.hpp"
#include "predicates/point.hpp"

#include <string>
#include <vector>

namespace anisocert {

using Point = predicates::Point2<Rational>;
using Metric = predicates::Sym2<Rational>;             // [m11 m12; m12 m22], symmetric positive definite
using Mesh = geometry::Mesh<Rational>;                 // sites, metrics, domain, segments, edges, triangles
using DoubleMesh = geometry::Mesh<double>;             // a mesher's own: each double is the rational it is
using DoubleMetric = predicates::Sym2<double>;
using Point3 = predicates::Point3<Rational>;
using Metric3 = predicates::Sym3<Rational>;            // [m11 m12 m13; m12 m22 m23; m13 m23 m33]
using Mesh3 = geometry::Mesh3<Rational>;               // vertices, metrics, tetrahedra, declared boundary triangles
using DoubleMesh3 = geometry::Mesh3<double>;
using DoubleMetric3 = predicates::Sym3<double>;
using oracle::CertifyOptions;                          // which checks, and the bounds to check
using oracle::Certify3Options;                         // the same for tetrahedra: valid, uniform, metric (lengths)
using io::MeshFile;                                    // a mesh as a file holds it (with references)
using io::InputError;                                  // a bad file

// The certifier's verdict: holds when every requested check holds.
template <class Report>
struct CertificateOf {
  bool holds = false;
  Report report;                  // the checks' findings (witnesses by triangle or tetrahedron, worst values)
  io::CertifyVerdict verdict;     // the same as one report, each check with its title and witnesses
  // The text `anisocert certify` prints (name: the first line's name for the mesh).
  std::string text(const std::string& name = "mesh") const;
  // The JSON `anisocert certify --json` writes (docs/cli.md documents every field).
  std::string json() const;
};
using Certificate = CertificateOf<oracle::CertifyReport>;
using Certificate3 = CertificateOf<oracle::Certify3Report>;

// Certifies mesh with metrics (one per site, in the order of mesh.sites), or with the mesh's own
// metrics when metrics is empty (none at all: only validity is checked). Throws
// std::invalid_argument, naming the index, for a metric count other than the site count, a metric
// that is not positive definite (exactly: m11 > 0 and m11 m22 − m12² > 0), a triangle, segment or
// edge naming no site, a domain that is not a simple counter-clockwise polygon, or a bound out of
// its range (rho0 > 0, gamma0 >= 1, 0 <= length range low <= high, min_quality in [0, 1],
// min_angle in (0, 90]).
Certificate certify(const Mesh& mesh, const std::vector<Metric>& metrics = {}, const CertifyOptions& options = {});
// The same in doubles: every double is taken as the rational it is (no rounding anywhere). Also
// throws std::invalid_argument for a NaN or infinite coordinate or metric entry.
Certificate certify(const DoubleMesh& mesh, const std::vector<DoubleMetric>& metrics = {},
                    const CertifyOptions& options = {});

// The rational mesh of a mesh in doubles, exactly; std::invalid_argument for NaN or infinities.
Mesh exact_mesh(const DoubleMesh& mesh);

// A tetrahedral mesh (issue 39), with metrics (one per vertex) or its own; the same exceptions,
// for a metric that is not positive definite (Sylvester's minors), a tetrahedron or triangle
// naming no vertex, or a bound out of its range (as for triangles).
Certificate3 certify(const Mesh3& mesh, const std::vector<Metric3>& metrics = {}, const Certify3Options& options = {});
Certificate3 certify(const DoubleMesh3& mesh, const std::vector<DoubleMetric3>& metrics = {},
                     const Certify3Options& options = {});
Mesh3 exact_mesh(const DoubleMesh3& mesh);

// Reads a mesh file in any format (by extension, or by format's name: medit, gmsh, triangle,
// freefem, json, ...), with per-vertex metrics from metric_path when given (a Medit .sol, a BAMG
// .mtr); every number is the rational its text denotes. Throws InputError.
MeshFile read_mesh(const std::string& path, const std::string& metric_path = "", const std::string& format = "");

// Writes m to path in the format of its extension (or format's name), with the files it implies
// beside it (a Medit .sol when m has metrics, Triangle's .node and .ele, ...). Throws InputError for
// a number the format cannot hold exactly or an unknown extension, std::runtime_error when a file
// cannot be written (no file is left half-written). Returns the paths written.
std::vector<std::string> write_mesh(const MeshFile& m, const std::string& path, const std::string& format = "");
// A mesh without a file's references.
std::vector<std::string> write_mesh(const Mesh& m, const std::string& path, const std::string& format = "");

}  // namespace anisocert
