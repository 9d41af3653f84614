// `anisocert dual MESH [--metric FILE | --field NAME]`: is a mesh the dual of the anisotropic
// Voronoi diagram of its own vertices (LS §5, Theorem 7)? The exact D|Ω of the mesh's vertices
// with their metrics, Ω the boundary of its triangles (geometry/boundary_polygon.hpp), compared
// triangle by triangle (oracle/diagram/mesh_dual.hpp). Exit 0 it is the dual, 1 it is not, 2 bad
// input (nothing written), 3 Theorem 7's preconditions hold and its conclusion fails.
#include "cli/diagram_job.hpp"
#include "cli/mesh_input.hpp"
#include "cli/output.hpp"
#include "cli/usage_error.hpp"
#include "geometry/boundary_polygon.hpp"
#include "io/reports/dual_report.hpp"

#include <CLI/CLI.hpp>

#include <memory>

namespace anisocert::cli {
namespace {

struct DualOptions {
  MeshInput in;
  std::string json_path, svg_path;
  DiagramOutputs diagram;  // quiet, exact_only, threads (its paths unused)
};

constexpr std::size_t described_witnesses = 100;

int run_dual(const DualOptions& o) {
  check_outputs({o.json_path, o.svg_path});  // before the diagram, which can take minutes
  io::MeshFile file = read_mesh_input(o.in);
  if (file.dimension == 3)
    throw UsageError(o.in.path + " is a tetrahedral mesh: `dual` asks Labelle and Shewchuk's planar question of triangle meshes");
  geometry::Mesh<Rational>& mesh = file.mesh;
  if (mesh.triangles.empty()) throw UsageError(o.in.path + ": the file has no triangles");
  if (mesh.metrics.empty()) throw UsageError(o.in.path + ": has no metric, which the diagram needs (give --metric FILE or --field NAME)");
  geometry::Mesh<Rational> sites;
  sites.sites = mesh.sites, sites.metrics = mesh.metrics;
  try {
    sites.domain = geometry::boundary_polygon(mesh);
  } catch (const std::invalid_argument& e) {
    throw UsageError(o.in.path + ": " + e.what());
  }
  const oracle::Diagram d = exact_diagram(sites, o.in.path, o.diagram);
  const oracle::MeshDual m = oracle::compare_with_dual(d, mesh.triangles, described_witnesses);
  std::vector<OutputFile> files;
  if (!o.json_path.empty()) files.push_back({o.json_path, render(io::dual_json(d, m, file.metric_source))});
  if (!o.svg_path.empty())
    files.push_back({o.svg_path, io::dual_svg(mesh, d, m, o.in.path + (m.is_dual() ? ": the dual of D|Ω" : ": not the dual of D|Ω"))});
  write_files_atomically(files);
  emit(io::dual_text(d, m, o.in.path, file.metric_source));
  if (const int code = theorem7_exit_code(d)) return code;
  return m.is_dual() ? 0 : 1;
}

}  // namespace

void add_dual(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DualOptions>();
  CLI::App* c = app.add_subcommand(
      "dual",
      "Is the mesh the dual of the anisotropic Voronoi diagram of its own vertices (Labelle–Shewchuk)? Computes D|Ω\n"
      "exactly — the mesh's vertices with their metrics, Ω the boundary of its triangles (one simple loop) — and\n"
      "decides each triangle: dual (its vertices own one Voronoi vertex), a tie (three of the four or more owners of\n"
      "one), or not dual (with the arcs or vertices that show it); lists the dual triangles the mesh lacks, orphans,\n"
      "unwedged arcs and vertices, and the Theorem 7 verdict. Mesh and metric as for certify.\n"
      "Exit 0 the mesh is the dual, 1 it is not, 2 bad input (one line, nothing written), 3 Theorem 7 contradicted.");
  add_mesh_input_options(c, o->in);
  c->add_option("--json", o->json_path,
                "write the report to this file: counts, and the first " + std::to_string(described_witnesses) + " witnesses of each list");
  c->add_option("--svg", o->svg_path, "write a picture: triangles dual, tied and not dual coloured, missing dual triangles outlined");
  c->add_flag("--quiet", o->diagram.quiet, "no progress lines on standard error");
  c->add_flag("--exact-only", o->diagram.exact_only,
              "build every point of the diagram with exact arithmetic (no interval filters first); same answers, slower");
  c->add_option("--threads", o->diagram.threads, "threads for the diagram (default: every core)")->check(CLI::Range(1, 1024));
  c->callback([o, &exit_code] { exit_code = run_dual(*o); });
}

}  // namespace anisocert::cli
