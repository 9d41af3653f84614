// `anisocert metric --field NAME (--at MESH | --grid N) -o FILE...`: a metric field written for
// another mesher, so that a peer meshes for exactly the field anisocert certifies against (one
// source of the formulas: fields/). At a mesh's vertices (a BAMG .mtr for FreeFem's adaptmesh, a
// Medit .sol for MMG) or on a grid of a box (a Gmsh tensor view .pos, Gmsh's BAMG background).
#include "cli/output.hpp"
#include "cli/usage_error.hpp"
#include "io/field_source.hpp"
#include "io/formats/registry.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <memory>

namespace anisocert::cli {
namespace {

struct MetricOptions {
  std::string field, at, format;
  std::vector<std::string> params, outputs, box{"0", "0", "1", "1"};
  int grid = 0;
};

// N × N cells of [x0, x1] × [y0, y1], two counter-clockwise triangles each; the coordinates are
// the doubles nearest x0 + (x1 − x0) i / N (a text format writes them exactly).
io::MeshFile grid_mesh(const MetricOptions& o) {
  std::array<double, 4> b{};
  for (int k = 0; k < 4; ++k) b[k] = parse_option("--box", o.box[k]).convert_to<double>();
  if (!(b[0] < b[2] && b[1] < b[3])) throw UsageError("--box X0 Y0 X1 Y1: expected X0 < X1 and Y0 < Y1");
  const int n = o.grid;
  io::MeshFile f;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      f.mesh.sites.push_back({rational_from_double(b[0] + (b[2] - b[0]) * i / n), rational_from_double(b[1] + (b[3] - b[1]) * j / n)});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      f.mesh.triangles.push_back({a, a + 1, a + n + 2});
      f.mesh.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  return f;
}

bool is_metric_file(const std::string& path) {
  for (const io::MetricFormat& f : io::metric_formats())
    for (const std::string& e : f.extensions)
      if (path.ends_with(e)) return true;
  return false;
}

// Each -o: a metric file (a tetrahedral mesh's only in a format that holds 3×3 metrics, a Medit
// .sol/.solb) or the mesh's own files with their metrics; all written or none.
std::vector<OutputFile> output_files(const MetricOptions& o, const io::MeshFile& f) {
  std::vector<OutputFile> files;
  try {
    for (const std::string& path : o.outputs) {
      if (is_metric_file(path)) {
        const io::MetricFormat& format = io::metric_format_of(path);
        if (f.dimension == 3 && !format.write3)
          throw UsageError(path + ": a " + format.name + " metric file holds 2D metrics only (use a Medit .sol)");
        io::FileText t = f.dimension == 3 ? format.write3(f.mesh3.metrics, path) : format.write(f.mesh.metrics, path);
        files.push_back({std::move(t.path), std::move(t.content)});
      } else {
        for (io::FileText& t : io::mesh_format_to_write(path).write(f, path)) files.push_back({std::move(t.path), std::move(t.content)});
      }
    }
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  return files;
}

int run_metric(const MetricOptions& o) {
  if (o.at.empty() == (o.grid == 0)) throw UsageError("give one of --at MESH and --grid N");
  io::MeshFile f;
  try {
    f = o.grid ? grid_mesh(o) : io::read_mesh_file(o.at, o.format);
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  if (f.dimension == 3) {  // a built-in 3D field at a tetrahedral mesh's vertices
    f.mesh3.metrics = io::metrics3_at(o.field, o.params, f.mesh3.vertices);
  } else {
    io::FieldSource source = io::field_source(o.field, o.params);
    // A file holds decimals or doubles, and a background mesh's exact P1 values are rationals with
    // no finite decimal expansion in general: every field is written at its doubles.
    source.background = nullptr;
    f.mesh.metrics = io::metrics_at(source, o.field, f.mesh.sites);
  }
  const std::vector<OutputFile> files = output_files(o, f);
  write_files_atomically(files);
  std::string written;
  for (const OutputFile& file : files) written += (written.empty() ? "" : ", ") + file.path;
  const std::size_t n = f.dimension == 3 ? f.mesh3.vertices.size() : f.mesh.sites.size();
  emit("metric: field " + o.field + " at " + std::to_string(n) + " vertices of " +
       (o.grid ? "a " + std::to_string(o.grid) + " x " + std::to_string(o.grid) + " grid" : o.at) + ": " + written + "\n");
  return 0;
}

}  // namespace

void add_metric(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<MetricOptions>();
  CLI::App* c = app.add_subcommand(
      "metric",
      "A metric field written for another mesher, so that it meshes for exactly the field that `anisocert certify\n"
      "--field` checks: at the vertices of a mesh (--at; e.g. a BAMG .mtr for FreeFem's adaptmesh, a Medit .sol for\n"
      "MMG) or on an N x N grid of a box (--grid; e.g. a Gmsh tensor view .pos, the background field of Gmsh's BAMG).\n"
      "Each -o is written in the format of its extension: a metric file (.mtr, .sol, .solb: the metrics only) or a\n"
      "mesh file with its metrics (.pos, .msh, .mesh, .json, ...). Values are the field's doubles (a background\nmesh's too), written exactly.\n"
      "Example: anisocert metric --field shock --grid 100 --box -0.01 -0.01 1.01 1.01 -o bg.pos");
  c->add_option("--field", o->field, "a built-in field (see refine --help) or background:MESH[:METRIC]")->required();
  c->add_option("--param", o->params, "a parameter of the built-in field, name=value (repeatable)");
  CLI::Option* at = c->add_option("--at", o->at, "the mesh at whose vertices to write the metric");
  c->add_option("--format", o->format, "the format of --at, when the extension does not tell")->needs(at);
  // A .pos triangle takes about 2 KB (each double's exact decimal expansion): 400 x 400 cells are 640 MB.
  CLI::Option* grid = c->add_option("--grid", o->grid, "N: an N x N grid of --box, two triangles per cell (N at most 400)")
                          ->check(CLI::Range(1, 400));
  c->add_option("--box", o->box, "X0 Y0 X1 Y1 of --grid (exact decimals)")->expected(4)->capture_default_str()->needs(grid);
  c->add_option("-o,--output", o->outputs, "a file to write (repeatable; all are written or none)")->required();
  c->callback([o, &exit_code] { exit_code = run_metric(*o); });
}

}  // namespace anisocert::cli
