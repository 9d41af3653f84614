#include "cli/mesh_input.hpp"

#include "cli/usage_error.hpp"
#include "io/field_source.hpp"
#include "io/formats/registry.hpp"

namespace anisocert::cli {

void add_mesh_input_options(CLI::App* c, MeshInput& in) {
  c->add_option("mesh", in.path, "the mesh file")->required();
  c->add_option("--format", in.format, "the mesh format, when the extension does not tell");
  c->add_option("--metric", in.metric,
                "per-vertex metrics in a separate file (.sol/.solb, .mtr); a Medit BASE.mesh reads BASE.sol beside it\n"
                "without this option, as MMG does");
  c->add_option("--metric-format", in.metric_format, "the metric file's format (medit, bamg)");
  c->add_option("--field", in.field, std::string("a metric field instead: a built-in name (see refine --help; for a tetrahedral mesh\n"
                                                     "    constant (m11 m12 m13 m22 m23 m33), ugawg-linear, ugawg-polar1, ugawg-polar2, parameter h0) or\n") +
                                         io::background_field_help);
  c->add_option("--param", in.params, "a parameter of the built-in field, name=value (repeatable)");
  c->add_flag("--planar-3d", in.planar_3d, "read a 3D Medit file whose every z is 0 as a 2D mesh");
}

io::MeshFile read_mesh_input(const MeshInput& in) {
  if (!in.metric.empty() && !in.field.empty()) throw UsageError("--metric and --field: give one metric source");
  io::MeshFile file;
  try {
    file = io::read_mesh_file(in.path, in.format, {in.planar_3d}, in.metric, in.metric_format);
    if (!in.field.empty() && file.dimension == 3) {
      io::attach_metrics(file, io::metrics3_at(in.field, in.params, file.mesh3.vertices), "--field " + in.field);
      file.metric_source = "--field " + in.field;
    } else if (!in.field.empty()) {
      io::attach_metrics(file, io::metrics_at(io::field_source(in.field, in.params), in.field, file.mesh.sites), "--field " + in.field);
      file.metric_source = "--field " + in.field;
    }
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  return file;
}

}  // namespace anisocert::cli
