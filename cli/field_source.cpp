#include "cli/field_source.hpp"

#include "cli/output.hpp"
#include "cli/usage_error.hpp"
#include "fields/registry.hpp"
#include "io/formats/registry.hpp"
#include "numbers/excerpt.hpp"

namespace anisocert::cli {
namespace {

constexpr std::string_view background_prefix = "background:";

// The --param values, "name=value" each, exactly parsed then rounded to doubles (the fields' type).
fields::Parameters parameters_of(const std::vector<std::string>& params) {
  fields::Parameters p;
  for (const std::string& kv : params) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw UsageError("--param " + quoted_excerpt(kv) + ": expected name=value");
    const std::string name = kv.substr(0, eq);
    if (p.count(name)) throw UsageError("--param " + quoted_excerpt(name) + " is given twice");
    p[name] = option_double("--param " + excerpt(name), kv.substr(eq + 1));
  }
  return p;
}

// MESH[:METRIC] after "background:".
FieldSource background_source(const std::string& text) {
  const std::string spec = text.substr(background_prefix.size());
  const auto colon = spec.find(':');
  const std::string mesh_path = spec.substr(0, colon), metric_path = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (mesh_path.empty() || (colon != std::string::npos && metric_path.empty()))
    throw UsageError("--field " + quoted_excerpt(text) + ": expected background:MESH or background:MESH:METRIC");
  if (!metric_path.empty() && !io::has_metric_extension(metric_path))
    throw UsageError("--field " + quoted_excerpt(text) + ": " + metric_path +
                     " is not a metric file (.sol, .solb, .mtr); a mesh whose own files hold its metrics (a Gmsh .msh with a metric view, a "
                     "Medit .mesh with its .sol beside it) is given alone: background:MESH");
  io::MeshFile file;
  try {
    // A planar mesh saved in 3D (every z 0, as Gmsh writes Medit files) is read as 2D: a field's
    // points are 2D, and a z that is not 0 is still refused.
    file = io::read_mesh_file(mesh_path, "", {true}, metric_path);
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  if (file.dimension == 3) throw UsageError(mesh_path + ": a tetrahedral mesh is no background for a 2D field");
  if (file.mesh.metrics.empty()) throw UsageError(mesh_path + ": background mesh has no metric (give MESH:METRIC)");
  try {
    auto mesh = std::make_shared<const fields::BackgroundMesh>(file.mesh);
    return {fields::background_field(mesh, text), mesh};
  } catch (const fields::BackgroundMeshError& e) {
    throw UsageError(mesh_path + ": " + e.what());
  }
}

}  // namespace

FieldSource field_source(const std::string& text, const std::vector<std::string>& params) {
  const fields::Parameters given = parameters_of(params);
  if (text.starts_with(background_prefix)) {
    if (!given.empty()) throw UsageError("--param: a background field has no parameters");
    return background_source(text);
  }
  try {
    return {fields::make_field(text, given), nullptr};
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--field: ") + e.what());
  }
}

std::vector<predicates::Sym2<Rational>> metrics_at(const FieldSource& source, const std::string& text,
                                                   const std::vector<predicates::Point2<Rational>>& points) {
  std::vector<predicates::Sym2<Rational>> metrics;
  metrics.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if (source.background) {
      const auto m = source.background->metric_at(p);
      if (!m) throw UsageError("--field " + text + ": vertex " + std::to_string(i) + " " + geometry::point_excerpt(p) +
                               " lies outside the background mesh");
      metrics.push_back(*m);
    } else {
      try {
        const auto m = source.field.at(p.x.convert_to<double>(), p.y.convert_to<double>());
        metrics.push_back({rational_from_double(m.m11), rational_from_double(m.m12), rational_from_double(m.m22)});
      } catch (const std::invalid_argument& e) {  // fields::FieldError, or NumberSyntaxError (not finite)
        throw UsageError("--field " + text + ": at vertex " + std::to_string(i) + ": " + e.what());
      }
      // In doubles a field can round to a metric that is not positive definite (underflow to 0,
      // cancellation at a large anisotropy): decided exactly, as for a metric read from a file.
      if (!predicates::positive_definite(metrics.back()))
        throw UsageError("--field " + text + ": at vertex " + std::to_string(i) + " " + geometry::point_excerpt(p) +
                         ", the field's metric in doubles is not positive definite (m11 m12 m22 = " +
                         exact_excerpt(metrics.back().m11) + " " + exact_excerpt(metrics.back().m12) + " " +
                         exact_excerpt(metrics.back().m22) + ")");
    }
  }
  return metrics;
}

}  // namespace anisocert::cli
