// `anisocert certify MESH.json`: the exact mesh certifier (oracle/certify/mesh_certifier.hpp). Exit 0
// when every requested check holds, 1 with witnesses when one fails, 2 for bad input.
#include "cli/output.hpp"
#include "cli/reports/certify_report.hpp"
#include "cli/usage_error.hpp"
#include "io/mesh_json.hpp"

#include <CLI/CLI.hpp>

#include <memory>

namespace anisocert::cli {
namespace {

struct CertifyCommandOptions {
  std::string input, json_path, rho0, gamma0;
  std::vector<std::string> checks{"valid", "uniform"};
};

int run_certify(const CertifyCommandOptions& c) {
  oracle::CertifyOptions o;
  o.valid = o.uniform = false;
  for (const std::string& k : c.checks) {
    if (k == "valid") o.valid = true;
    else if (k == "uniform") o.uniform = true;
    else throw UsageError("--checks: unknown check \"" + k + "\" (valid, uniform)");
  }
  if (!c.rho0.empty()) o.rho0 = parse_option("--rho0", c.rho0);
  if (!c.gamma0.empty()) o.gamma0 = parse_option("--gamma0", c.gamma0);
  if (o.rho0 && *o.rho0 <= 0) throw UsageError("--rho0 must be positive");
  if (o.gamma0 && *o.gamma0 < 1) throw UsageError("--gamma0 must be at least 1");
  geometry::Mesh<Rational> mesh;
  try {
    mesh = io::read_triangle_mesh_file(c.input);
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  const CertifyVerdict v = certify_verdict(oracle::certify_mesh(mesh, o), o, mesh, c.rho0, c.gamma0);
  if (!c.json_path.empty()) write_file_atomically(c.json_path, render(to_json(v)));
  emit(full_text(v, c.input));
  return v.holds ? 0 : 1;
}

}  // namespace

void add_certify(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CertifyCommandOptions>();
  CLI::App* c = app.add_subcommand(
      "certify",
      "Exact checks of a triangle mesh with per-vertex metrics (the site-set format plus \"triangles\": [[i, j, k], ...],\n"
      "counter-clockwise; numbers are read exactly from their text): valid (a triangulation of the domain, every\n"
      "segment a union of edges), locally uniform (every triangle at a vertex v has an empty circumellipse in M_v,\n"
      "ties reported apart), and, when thresholds are given, the radius-edge ratio in each vertex's metric and the\n"
      "distortion between the vertices of each triangle. Exit 0 all hold, 1 a check fails (witnesses), 2 bad input.");
  c->add_option("mesh", o->input, "the mesh (JSON)")->required();
  c->add_option("--checks", o->checks, "which of valid, uniform to run (default both)")->delimiter(',');
  c->add_option("--rho0", o->rho0, "check radius-edge ratio <= this (exact rational)");
  c->add_option("--gamma0", o->gamma0, "check distortion <= this (exact rational)");
  c->add_option("--json", o->json_path, "write the full report to this file");
  c->callback([o, &exit_code] { exit_code = run_certify(*o); });
}

}  // namespace anisocert::cli
