#include "io/field_source.hpp"

#include "fields/background3.hpp"
#include "fields/registry.hpp"
#include "io/formats/registry.hpp"
#include "numbers/excerpt.hpp"

#include <cmath>

namespace anisocert::io {

double option_double(const std::string& name, const std::string& text) {
  Rational q;
  try {
    q = parse_input_number(text);
  } catch (const NumberSyntaxError& e) {
    throw InputError(name + ": " + e.what());
  }
  const double d = q.convert_to<double>();
  if (!std::isfinite(d)) throw InputError(name + " " + quoted_excerpt(text) + " is beyond the range of doubles");
  if (d == 0 && q != 0) throw InputError(name + " " + quoted_excerpt(text) + " is below the range of doubles (it would read as 0)");
  return d;
}

namespace {

constexpr std::string_view background_prefix = "background:";

// The --param values, "name=value" each, exactly parsed then rounded to doubles (the fields' type).
fields::Parameters parameters_of(const std::vector<std::string>& params) {
  fields::Parameters p;
  for (const std::string& kv : params) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw InputError("--param " + quoted_excerpt(kv) + ": expected name=value");
    const std::string name = kv.substr(0, eq);
    if (p.count(name)) throw InputError("--param " + quoted_excerpt(name) + " is given twice");
    p[name] = option_double("--param " + excerpt(name), kv.substr(eq + 1));
  }
  return p;
}

// The mesh file of background:MESH[:METRIC], with its metrics.
io::MeshFile background_file(const std::string& text) {
  const std::string spec = text.substr(background_prefix.size());
  const auto colon = spec.find(':');
  const std::string mesh_path = spec.substr(0, colon), metric_path = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (mesh_path.empty() || (colon != std::string::npos && metric_path.empty()))
    throw InputError("--field " + quoted_excerpt(text) + ": expected background:MESH or background:MESH:METRIC");
  if (!metric_path.empty() && !io::has_metric_extension(metric_path))
    throw InputError("--field " + quoted_excerpt(text) + ": " + metric_path +
                     " is not a metric file (.sol, .solb, .mtr); a mesh whose own files hold its metrics (a Gmsh .msh with a metric view, a "
                     "Medit .mesh with its .sol beside it) is given alone: background:MESH");
  // A planar mesh saved in 3D (every z 0, as Gmsh writes Medit files) is read as 2D: a field's
  // points are 2D, and a z that is not 0 is still refused.
  io::MeshFile file = io::read_mesh_file(mesh_path, "", {true}, metric_path);
  if (file.dimension == 3 ? file.mesh3.metrics.empty() : file.mesh.metrics.empty())
    throw InputError(mesh_path + ": background mesh has no metric (give MESH:METRIC)");
  return file;
}

FieldSource background_source(const std::string& text) {
  const io::MeshFile file = background_file(text);
  if (file.dimension == 3) throw InputError(text.substr(background_prefix.size()) + ": a tetrahedral mesh is no background for a 2D field");
  try {
    auto mesh = std::make_shared<const fields::BackgroundMesh>(file.mesh);
    return {fields::background_field(mesh, text), mesh};
  } catch (const fields::BackgroundMeshError& e) {
    throw InputError(text.substr(background_prefix.size()) + ": " + e.what());
  }
}

}  // namespace

FieldSource field_source(const std::string& text, const std::vector<std::string>& params) {
  const fields::Parameters given = parameters_of(params);
  if (text.starts_with(background_prefix)) {
    if (!given.empty()) throw InputError("--param: a background field has no parameters");
    return background_source(text);
  }
  try {
    return {fields::make_field(text, given), nullptr};
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--field: ") + e.what());
  }
}

namespace {

std::string point_text(const predicates::Point2<Rational>& p) { return geometry::point_excerpt(p); }
std::string point_text(const predicates::Point3<Rational>& p) {
  return "(" + exact_excerpt(p.x) + ", " + exact_excerpt(p.y) + ", " + exact_excerpt(p.z) + ")";
}

predicates::Sym2<double> evaluate(const fields::MetricField& f, const predicates::Point2<Rational>& p) {
  return f.at(p.x.convert_to<double>(), p.y.convert_to<double>());
}
predicates::Sym3<double> evaluate(const fields::MetricField3& f, const predicates::Point3<Rational>& p) {
  return f.at(p.x.convert_to<double>(), p.y.convert_to<double>(), p.z.convert_to<double>());
}

predicates::Sym2<Rational> exactly(const predicates::Sym2<double>& m) {
  return {rational_from_double(m.m11), rational_from_double(m.m12), rational_from_double(m.m22)};
}
predicates::Sym3<Rational> exactly(const predicates::Sym3<double>& m) {
  return {rational_from_double(m.m11), rational_from_double(m.m12), rational_from_double(m.m13),
          rational_from_double(m.m22), rational_from_double(m.m23), rational_from_double(m.m33)};
}

std::string entries_text(const predicates::Sym2<Rational>& m) {
  return "m11 m12 m22 = " + exact_excerpt(m.m11) + " " + exact_excerpt(m.m12) + " " + exact_excerpt(m.m22);
}
std::string entries_text(const predicates::Sym3<Rational>& m) {
  return "m11 m12 m13 m22 m23 m33 = " + exact_excerpt(m.m11) + " " + exact_excerpt(m.m12) + " " + exact_excerpt(m.m13) + " " +
         exact_excerpt(m.m22) + " " + exact_excerpt(m.m23) + " " + exact_excerpt(m.m33);
}

// A built-in field at point i's nearest doubles, its double values taken as the rationals they
// are. In doubles a field can round to a metric that is not positive definite (underflow to 0,
// cancellation at a large anisotropy): decided exactly, as for a metric read from a file.
template <class Field, class P>
auto sampled(const Field& field, const std::string& text, const P& p, std::size_t i) {
  decltype(exactly(evaluate(field, p))) m;
  try {
    m = exactly(evaluate(field, p));
  } catch (const std::invalid_argument& e) {  // fields::FieldError, or NumberSyntaxError (not finite)
    throw InputError("--field " + text + ": at vertex " + std::to_string(i) + ": " + e.what());
  }
  if (!predicates::positive_definite(m))
    throw InputError("--field " + text + ": at vertex " + std::to_string(i) + " " + point_text(p) +
                     ", the field's metric in doubles is not positive definite (" + entries_text(m) + ")");
  return m;
}

}  // namespace

std::vector<predicates::Sym2<Rational>> metrics_at(const FieldSource& source, const std::string& text,
                                                   const std::vector<predicates::Point2<Rational>>& points) {
  std::vector<predicates::Sym2<Rational>> metrics;
  metrics.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if (source.background) {
      const auto m = source.background->metric_at(p);
      if (!m) throw InputError("--field " + text + ": vertex " + std::to_string(i) + " " + geometry::point_excerpt(p) +
                               " lies outside the background mesh");
      metrics.push_back(*m);
    } else {
      metrics.push_back(sampled(source.field, text, p, i));
    }
  }
  return metrics;
}

fields::MetricField3 field3_source(const std::string& text, const std::vector<std::string>& params) {
  const fields::Parameters given = parameters_of(params);
  if (text.starts_with(background_prefix)) {
    if (!given.empty()) throw InputError("--param: a background field has no parameters");
    const io::MeshFile file = background_file(text);
    if (file.dimension != 3) throw InputError(text.substr(background_prefix.size()) + ": a triangle mesh is no background for a 3D domain");
    std::shared_ptr<const fields::BackgroundMesh3> mesh;
    try {
      mesh = std::make_shared<const fields::BackgroundMesh3>(file.mesh3);
    } catch (const fields::BackgroundMeshError& e) {
      throw InputError(text.substr(background_prefix.size()) + ": " + e.what());
    }
    return {text, {}, [mesh, text](double x, double y, double z) {
              const auto m = mesh->metric_at({rational_from_double(x), rational_from_double(y), rational_from_double(z)});
              if (!m) throw fields::FieldError("the background mesh of " + text + " does not cover the point (" + std::to_string(x) + ", " +
                                               std::to_string(y) + ", " + std::to_string(z) + ")");
              return predicates::Sym3<double>{m->m11.convert_to<double>(), m->m12.convert_to<double>(), m->m13.convert_to<double>(),
                                              m->m22.convert_to<double>(), m->m23.convert_to<double>(), m->m33.convert_to<double>()};
            }};
  }
  try {
    return fields::make_field3(text, given);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--field: ") + e.what());
  }
}

std::vector<predicates::Sym3<Rational>> metrics3_at(const std::string& text, const std::vector<std::string>& params,
                                                    const std::vector<predicates::Point3<Rational>>& points) {
  const fields::Parameters given = parameters_of(params);
  std::vector<predicates::Sym3<Rational>> metrics;
  metrics.reserve(points.size());
  if (text.starts_with(background_prefix)) {
    if (!given.empty()) throw InputError("--param: a background field has no parameters");
    const io::MeshFile file = background_file(text);
    if (file.dimension != 3) throw InputError(text.substr(background_prefix.size()) + ": a triangle mesh is no background for a tetrahedral mesh");
    std::optional<fields::BackgroundMesh3> mesh;
    try {
      mesh.emplace(file.mesh3);
    } catch (const fields::BackgroundMeshError& e) {
      throw InputError(text.substr(background_prefix.size()) + ": " + e.what());
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto m = mesh->metric_at(points[i]);
      if (!m) throw InputError("--field " + text + ": vertex " + std::to_string(i) + " " + point_text(points[i]) + " lies outside the background mesh");
      metrics.push_back(*m);
    }
    return metrics;
  }
  fields::MetricField3 field;
  try {
    field = fields::make_field3(text, given);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--field: ") + e.what());
  }
  for (std::size_t i = 0; i < points.size(); ++i) metrics.push_back(sampled(field, text, points[i], i));
  return metrics;
}

}  // namespace anisocert::io
