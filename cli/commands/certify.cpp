// `anisocert certify MESH [--metric FILE | --field NAME]`: the exact mesh certifier
// (oracle/certify/mesh_certifier.hpp) on a mesh in any format of io/formats/registry.hpp. Exit 0
// when every requested check holds, 1 with witnesses when one fails, 2 for bad input (nothing
// written).
#include "cli/mesh_input.hpp"
#include "cli/output.hpp"
#include "cli/usage_error.hpp"
#include "io/formats/registry.hpp"
#include "io/reports/certify_report.hpp"
#include "io/svg/certify_svg.hpp"
#include "numbers/excerpt.hpp"

#include <CLI/CLI.hpp>

#include <memory>

namespace anisocert::cli {
namespace {

struct CertifyCommandOptions {
  MeshInput in;
  std::string json_path, svg_path;
  io::BoundTexts bounds;
  std::vector<std::string> length_range;
  std::vector<std::string> checks{"valid", "uniform", "metric"};
  bool checks_given = false;   // --checks was on the command line
  bool all_witnesses = false;
  int threads = 0;
};

oracle::CertifyOptions certify_options(CertifyCommandOptions& c) {
  oracle::CertifyOptions o;
  o.valid = o.uniform = o.metric = false;
  o.described_witnesses = c.all_witnesses ? oracle::all_witnesses : oracle::default_described_witnesses;
  o.threads = c.threads;
  for (const std::string& k : c.checks) {
    if (k == "valid") o.valid = true;
    else if (k == "uniform") o.uniform = true;
    else if (k == "metric") o.metric = true;
    else throw UsageError("--checks: unknown check " + quoted_excerpt(k) + " (valid, uniform, metric)");
  }
  const io::BoundTexts& b = c.bounds;
  if (!b.rho0.empty()) o.rho0 = parse_option("--rho0", b.rho0);
  if (!b.gamma0.empty()) o.gamma0 = parse_option("--gamma0", b.gamma0);
  if (o.rho0 && *o.rho0 <= 0) throw UsageError("--rho0 must be positive");
  if (o.gamma0 && *o.gamma0 < 1) throw UsageError("--gamma0 must be at least 1");
  if (!c.length_range.empty()) {
    c.bounds.length_lo = c.length_range[0], c.bounds.length_hi = c.length_range[1];
    o.length_range = {parse_option("--length-range", c.length_range[0]), parse_option("--length-range", c.length_range[1])};
    if (o.length_range->first < 0 || o.length_range->first > o.length_range->second)
      throw UsageError("--length-range: expected 0 <= a <= b");
  }
  if (!b.min_quality.empty()) {
    o.min_quality = parse_option("--min-quality", b.min_quality);
    if (*o.min_quality < 0 || *o.min_quality > 1) throw UsageError("--min-quality must be in [0, 1]");
  }
  if (!b.min_angle.empty()) {
    o.min_angle = parse_option("--min-angle", b.min_angle);
    if (*o.min_angle <= 0 || *o.min_angle > 90) throw UsageError("--min-angle must be in (0, 90] degrees");
  }
  if ((o.length_range || o.min_quality || o.min_angle) && !o.metric)
    throw UsageError("--length-range, --min-quality and --min-angle need the metric check (--checks ...,metric)");
  return o;
}

// A tetrahedral mesh (issue 39): validity, local uniformity, edge lengths, quality and dihedral
// angles in 3D; the checks not yet written for tetrahedra are refused by name rather than skipped.
int run_certify3(CertifyCommandOptions& c, const oracle::CertifyOptions& o, const io::MeshFile& file) {
  const geometry::Mesh3<Rational>& mesh = file.mesh3;
  if (mesh.metrics.empty() && (o.length_range || o.min_quality || o.rho0 || o.gamma0 || (c.checks_given && (o.uniform || o.metric))))
    throw UsageError(c.in.path + ": has no metric, which the requested checks and bounds need (give --metric FILE)");
  oracle::Certify3Options o3;
  o3.valid = o.valid, o3.uniform = o.uniform, o3.metric = o.metric, o3.length_range = o.length_range;
  o3.min_quality = o.min_quality, o3.min_angle = o.min_angle, o3.rho0 = o.rho0, o3.gamma0 = o.gamma0;
  o3.described_witnesses = o.described_witnesses, o3.threads = o.threads;
  const oracle::Certify3Report report = oracle::certify_mesh3(mesh, o3);
  io::CertifyVerdict v = io::certify_verdict(report, o3, mesh, c.bounds);
  v.metric_source = file.metric_source;
  std::vector<OutputFile> files;
  if (!c.json_path.empty()) files.push_back({c.json_path, "", [&](std::ostream& out) { io::write_json(out, v, report); }});
  if (!c.svg_path.empty()) files.push_back({c.svg_path, io::certify_svg(mesh, report, c.in.path + (v.holds ? ": certified" : ": not certified"))});
  write_files_atomically(files);
  emit(io::full_text(v, c.in.path));
  return v.holds ? 0 : 1;
}

int run_certify(CertifyCommandOptions& c) {
  const oracle::CertifyOptions o = certify_options(c);
  io::MeshFile file = read_mesh_input(c.in);
  if (file.dimension == 3) return run_certify3(c, o, file);
  if (file.mesh.triangles.empty()) throw UsageError(c.in.path + ": the file has no triangles");
  if (file.mesh.metrics.empty()) {
    // A bound or a check the user asked for must run or be refused, never be skipped quietly.
    const bool asked = o.rho0 || o.gamma0 || o.length_range || o.min_quality || o.min_angle ||
                       (c.checks_given && (o.uniform || o.metric));
    if (asked)
      throw UsageError(c.in.path + ": has no metric, which the requested checks and bounds need (give --metric FILE or --field NAME)");
  }
  const oracle::CertifyReport report = oracle::certify_mesh(file.mesh, o);
  io::CertifyVerdict v = io::certify_verdict(report, o, file.mesh, c.bounds);
  v.metric_source = file.metric_source;
  std::vector<OutputFile> files;
  // Streamed: with --all-witnesses a bad mesh's report lists a witness per triangle.
  if (!c.json_path.empty()) files.push_back({c.json_path, "", [&](std::ostream& out) { io::write_json(out, v, report); }});
  if (!c.svg_path.empty()) files.push_back({c.svg_path, io::certify_svg(file.mesh, report, c.in.path + (v.holds ? ": certified" : ": not certified"))});
  write_files_atomically(files);
  emit(io::full_text(v, c.in.path));
  return v.holds ? 0 : 1;
}

std::string format_list() {
  std::string s;
  for (const auto& f : io::mesh_formats()) {
    s += "  " + f.name + ":";
    for (const auto& e : f.extensions) s += " " + e;
    s += "  " + f.summary + "\n";
  }
  s += "Metric files (--metric):\n";
  for (const auto& f : io::metric_formats()) {
    s += "  " + f.name + ":";
    for (const auto& e : f.extensions) s += " " + e;
    s += "  " + f.summary + "\n";
  }
  return s;
}

}  // namespace

void add_certify(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CertifyCommandOptions>();
  CLI::App* c = app.add_subcommand(
      "certify",
      "Exact checks of a triangle or tetrahedral mesh in any of the formats below (numbers are read as the rationals their text denotes,\n"
      "a binary double as the rational it is). Checks: valid (a triangulation of the domain — the file's boundary edges,\n"
      "or the boundary of the union of its triangles —, no two vertices coincide, required edges are unions of edges);\n"
      "locally uniform (every triangle at a vertex v has an empty circumellipse in M_v, ties reported apart); metric\n"
      "(edge lengths in the endpoints' metrics, the share in [1/sqrt2, sqrt2], mean-ratio qualities, angles), with\n"
      "bounds as verdicts; radius-edge ratio and distortion when thresholds are given. The metric: the file's own\n"
      "(Gmsh $NodeData, JSON; a Medit BASE.mesh's BASE.sol), --metric FILE, or --field. Without a metric only `valid`\n"
      "runs, and bounds that need one are refused. Each check's verdict stands on its own.\n"
      "A tetrahedral mesh (Medit Dimension 3 with Tetrahedra, Gmsh, TetGen, VTK .vtu; 3D metrics or a 3D field): valid (one\n"
      "orientation, each inner face in two tetrahedra on opposite sides, a closed 2-manifold boundary, declared triangles\n"
      "the boundary faces), locally uniform (empty M_v-circumspheres), --rho0, --gamma0, edge lengths, quality, dihedral\n"
      "angles (--min-angle) and UGAWG's measures; --svg draws a slice at mid-height and the histograms.\n"
      "Exit 0 all hold, 1 a check fails (witnesses), 2 bad input (one line, nothing written).\nMesh formats (by extension, or --format):\n" +
          format_list());
  add_mesh_input_options(c, o->in);
  CLI::Option* checks =
      c->add_option("--checks", o->checks, "which of valid, uniform, metric to run (default all)")->delimiter(',');
  c->add_option("--rho0", o->bounds.rho0, "check radius-edge ratio <= this (exact rational)");
  c->add_option("--gamma0", o->bounds.gamma0, "check distortion <= this (exact rational)");
  c->add_option("--length-range", o->length_range, "check every metric edge length in [a, b] (e.g. 0.7071 1.4143)")
      ->expected(2);
  c->add_option("--min-quality", o->bounds.min_quality, "check every mean-ratio quality in the metrics >= q");
  c->add_option("--min-angle", o->bounds.min_angle, "check every angle in its vertex's metric >= this many degrees (tetrahedra: every dihedral angle in each end of its edge's metric)");
  const std::string first = "the first " + std::to_string(oracle::default_described_witnesses);
  c->add_option("--json", o->json_path,
                "write the full report to this file: per check, the exact count of failures and " + first + "\n"
                "witnesses of each list (--all-witnesses: every one)");
  c->add_flag("--all-witnesses", o->all_witnesses,
              "list every witness in --json (one per failing triangle or edge: a bad mesh of a million triangles gives\n"
              "a million), not only " + first + " of each list");
  c->add_option("--svg", o->svg_path, "write a picture: the mesh, failures coloured, histograms of lengths and qualities");
  c->add_option("--threads", o->threads, "threads for the locally uniform check (default: every core; same report)")
      ->check(CLI::Range(1, 1024));
  c->callback([o, checks, &exit_code] {
    o->checks_given = checks->count() > 0;
    exit_code = run_certify(*o);
  });
}

}  // namespace anisocert::cli
