// `anisocert refine --algo NAME`: a refiner of the registry (refiners/registry.hpp) on a domain and a
// metric field (io/field_source.hpp: a built-in field or a background mesh); writes the mesh for
// `anisocert certify`, Medit .mesh/.sol and SVG.
#include "cli/coarsen.hpp"
#include "cli/diagram_job.hpp"
#include "cli/output.hpp"
#include "cli/refine_from.hpp"
#include "cli/relocate.hpp"
#include "cli/reports/refine_report.hpp"
#include "cli/usage_error.hpp"
#include "fields/registry.hpp"
#include "geometry/builtin_polyhedra.hpp"
#include "io/field_source.hpp"
#include "io/formats/polyhedron_file.hpp"
#include "io/reports/certify_report.hpp"
#include "io/svg/certify_svg.hpp"
#include "oracle/certify/mesh_certifier3.hpp"
#include "io/formats/registry.hpp"
#include "io/mesh_json.hpp"
#include "io/svg/diagram_svg.hpp"
#include "io/svg/mesh_svg.hpp"
#include "numbers/excerpt.hpp"
#include "oracle/diagram/mesh_dual.hpp"

#include <CLI/CLI.hpp>

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace anisocert::cli {

std::string refiners_where(bool dual_of_diagram);

namespace {

// "a, b, c"
std::string names_of(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

struct RefineOptions {
  std::string algo = "star", domain = "square", field = "shock", output, output_format, svg, json;
  CLI::Option* field_option = nullptr;
  CLI::Option* domain_option = nullptr;
  MeshInput from;  // --from MESH: its path, format, metric file (refine_from.hpp)
  bool exact_sites = false, coarsen = false, collapse = false, relocate = false;
  int threads = 0;
  std::vector<std::string> params;
  std::map<std::string, double> values;            // every refiner parameter's default
  std::map<std::string, std::string> texts;        // the values given, as typed (exact decimals or fractions)
  std::map<std::string, bool> flags;               // the parameters that are flags (refiners::ParameterSpec::flag)
  std::map<std::string, CLI::Option*> options;    // their options, to tell which were given
  std::string max_vertices, max_seconds;           // the budget as typed, when given
  CLI::Option* seed_option = nullptr;
  unsigned seed = 1;
  bool quiet = false;
};

// The picture for --svg, the line that names it, and whether Theorem 7's preconditions hold in the
// diagram drawn while its conclusion fails. For a refiner whose mesh is meant to be the dual of the
// exact diagram of its vertices, that diagram, D|Ω, computed by the oracle after the run, with its
// dual, and whether the mesh is that dual (LS §7: when D|Ω has no orphans, every loose diagram
// restricted to Ω is D|Ω). The mesh otherwise, or when the oracle declines the sites or runs out
// of memory on them (the caption says why: the run's mesh is still written).
struct Picture {
  std::string svg, line;
  std::optional<oracle::Diagram> diagram;  // when drawn
};
Picture picture(const refiners::RefinerEntry& entry, const geometry::Mesh<double>& m, const RefineOptions& o) {
  std::string what = entry.name + " refiner, field " + o.field;
  for (const auto& [name, given] : o.flags)
    if (given) what += " --" + name;  // --normalized-metric: the sites carry M′, and so does the diagram drawn
  what += ": " + std::to_string(m.sites.size()) + " vertices";
  if (!entry.dual_of_diagram) return {io::mesh_svg(m, what), "  picture: " + o.svg + "\n", std::nullopt};
  std::string declined;
  try {
    DiagramOutputs options;
    options.quiet = o.quiet;
    options.progress_label = "--svg: ";  // the run's lines are done
    oracle::Diagram d = exact_diagram(geometry::exact(m), "its sites", options);
    // A stopped run's mesh can be the dual of a diagram whose dual is no triangulation (flat or
    // overlapping triangles, which `dual` refuses to read): the caption says so.
    const bool is_dual = oracle::compare_with_dual(d, m.triangles, 0).is_dual();
    const std::string verdict = !is_dual                           ? "the mesh is not its dual"
                                : d.dual_check.is_triangulation ? "the mesh is its dual"
                                                                : "the mesh is its dual, which is no triangulation of Ω";
    std::string svg = io::diagram_svg(d, what + "; the exact D|Ω of its vertices and its dual (dashed): " + verdict);
    return {std::move(svg), "  picture: " + o.svg + " (the exact D|Ω of the final sites with its dual; " + verdict + ")\n", std::move(d)};
  } catch (const UsageError& e) {  // "its sites: why"
    declined = std::string("the oracle declined ") + e.what();
  } catch (const std::bad_alloc&) {
    declined = "the exact diagram did not fit in memory";
  }
  return {io::mesh_svg(m, what + " (the diagram is not drawn: " + declined + ")"), "  picture: " + o.svg + " (the mesh only: " + declined + ")\n",
          std::nullopt};
}

// The command that checks the files written: the mesh, and its metric file when another holds it
// (`dual` and `certify` find a Medit .sol beside its .mesh, not a FreeFem .mtr).
std::string check_command(const refiners::RefinerEntry& entry, const std::vector<std::string>& paths) {
  std::string command = entry.check() + " " + paths.front();
  for (std::size_t k = 1; k < paths.size(); ++k)
    if (io::has_metric_extension(paths[k])) command += " --metric " + paths[k];
  return command;
}

// The budget: the defaults of refiners::common::Budget, or a positive whole number of vertices and
// a positive number of seconds.
refiners::common::Budget budget_of(const RefineOptions& o) {
  refiners::common::Budget b;
  if (!o.max_vertices.empty()) {
    const Rational v = parse_option("--max-vertices", o.max_vertices);
    if (v < 1 || denominator(v) != 1 || v > Rational(std::numeric_limits<std::size_t>::max()))
      throw UsageError("--max-vertices " + quoted_excerpt(o.max_vertices) + ": expected a positive whole number");
    b.max_vertices = v.convert_to<std::size_t>();
  }
  if (!o.max_seconds.empty()) {
    b.max_seconds = io::option_double("--max-seconds", o.max_seconds);
    if (!(b.max_seconds > 0)) throw UsageError("--max-seconds " + quoted_excerpt(o.max_seconds) + ": expected a positive number");
  }
  return b;
}

// The files of `file` in `format` at `path`, added to `files` (their paths to `paths`); their
// names, joined for the report. A number the format cannot hold is bad input.
std::string mesh_files(const io::MeshFormat& format, const io::MeshFile& file, const std::string& path, std::vector<OutputFile>& files,
                       std::vector<std::string>& paths) {
  std::string written;
  try {
    for (io::FileText& f : format.write(file, path)) {
      written += (written.empty() ? "" : ", ") + f.path;
      paths.push_back(f.path);
      files.push_back({std::move(f.path), std::move(f.content)});
    }
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  return written;
}

// A 2D run's mesh (doubles, its boundary subsegments declared as every mesher's file declares them)
// in `format` at `path`, as mesh_files adds them.
std::string mesh_files(const io::MeshFormat& format, const geometry::Mesh<double>& m, const std::string& path, std::vector<OutputFile>& files,
                       std::vector<std::string>& paths) {
  io::MeshFile file;
  file.mesh = geometry::exact(m);
  file.mesh.edges = file.mesh.segments;
  return mesh_files(format, file, path, files, paths);
}

// `refine` on a polyhedron (issue 40): the run, its files, and the exact 3D certifier's verdict on
// its mesh (valid, locally uniform, ρ₀ and γ₀ met, LU's sliver measure at γ₀): exit 0 only when
// the run finished with consistent stars and the certifier certifies the mesh.
int run_refine3(const RefineOptions& o, const refiners::RefinerEntry& entry, const refiners::ParameterValues& values,
                const refiners::common::Budget& budget, const io::MeshFormat* format) {
  if (!entry.run3) throw UsageError("--algo " + o.algo + " meshes polygons only: --algo star meshes a 3D domain");
  geometry::Polyhedron polyhedron;
  if (const geometry::Polyhedron* builtin = geometry::builtin_polyhedron(o.domain)) {
    polyhedron = *builtin;
  } else {
    try {
      polyhedron = io::read_polyhedron_file(o.domain);
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
  }
  const std::string field_name = o.field_option->count() > 0 ? o.field : "ugawg-linear";
  const fields::MetricField3 field = io::field3_source(field_name, o.params);
  const auto progress = progress_printer(o.quiet);
  refiners::Run3 run;
  try {
    const refiners::common::Domain3 domain(polyhedron);
    run = entry.run3(domain, field, values, budget, o.seed, progress);
  } catch (const refiners::common::DomainError& e) {
    throw UsageError(o.domain + ": " + e.what());
  } catch (const refiners::common::FieldError& e) {
    throw UsageError(std::string("--field: ") + e.what());
  } catch (const refiners::ParameterError& e) {
    throw UsageError(e.what());
  }
  const auto& m = run.result.mesh;
  io::MeshFile file;
  file.dimension = 3;
  for (const auto& p : m.vertices) file.mesh3.vertices.push_back({rational_from_double(p.x), rational_from_double(p.y), rational_from_double(p.z)});
  for (const auto& M : m.metrics)
    file.mesh3.metrics.push_back({rational_from_double(M.m11), rational_from_double(M.m12), rational_from_double(M.m13),
                                  rational_from_double(M.m22), rational_from_double(M.m23), rational_from_double(M.m33)});
  file.mesh3.tetrahedra = m.tetrahedra;
  file.mesh3.triangles = m.triangles;
  file.tetrahedron_refs.assign(m.tetrahedra.size(), 0);
  file.triangle_refs.assign(m.triangles.size(), 0);
  file.vertex_refs.assign(m.vertices.size(), 0);
  // The certifier's verdict on the mesh as written (the rationals the files hold).
  if (!o.quiet) progress("refine: certifying the mesh (" + std::to_string(m.tetrahedra.size()) + " tetrahedra)");
  const io::RunCertificate3 certificate = io::certify_run3(file.mesh3, values.at("rho0"), values.at("gamma0"), o.threads, "--field " + field_name);
  const oracle::Certify3Report& report = certificate.report;
  const io::CertifyVerdict& verdict = certificate.verdict;
  std::vector<OutputFile> files;
  std::string written;
  std::vector<std::string> paths;
  if (format) {
    written = mesh_files(*format, file, o.output, files, paths);
  }
  if (!o.json.empty()) files.push_back({o.json, "", [&](std::ostream& out) { io::write_json(out, verdict, report); }});
  if (!o.svg.empty())
    files.push_back({o.svg, io::certify_svg(file.mesh3, report, "star refiner (3D), " + o.domain + ", field " + field_name + ": " +
                                                                   std::to_string(m.vertices.size()) + " vertices" +
                                                                   (verdict.holds ? ", certified" : ", not certified"))});
  write_files_atomically(files);
  std::string text = "refine: domain " + o.domain + ", field " + field_name + "\n";
  for (const std::string& line : run.report) text += line + "\n";
  if (format) text += "  mesh: " + written + " (check it with " + check_command(entry, paths) + ")\n";
  if (!o.svg.empty()) text += "  picture: " + o.svg + "\n";
  if (!o.json.empty()) text += "  certificate: " + o.json + "\n";
  text += io::full_text(verdict, "the run's mesh");
  emit(text);
  return run.result.consistent && verdict.holds ? 0 : 1;
}

// `refine --from MESH` (refine_from.hpp): the run from the mesh's vertices, its before/after report
// and the output's certificate; exit 0 only when the output is certified.
int run_refine_from(const RefineOptions& o, const refiners::RefinerEntry& entry, const refiners::ParameterValues& values,
                    const refiners::common::Budget& budget, const io::MeshFormat* format) {
  if (o.domain_option->count() > 0) throw UsageError("--domain and --from: the domain is the boundary of the mesh's triangles");
  MeshInput in = o.from;
  if (o.field_option->count() > 0) in.field = o.field, in.params = o.params;
  else if (!o.params.empty()) throw UsageError("--param without --field: the metric is the mesh's own");
  if (o.relocate && !entry.dual_of_diagram)
    throw UsageError("--relocate: --algo " + entry.name + " is certified locally uniform, and relocating keeps the exact dual (--algo " +
                     refiners_where(true) + ")");
  if (o.coarsen && !entry.dual_of_diagram)
    throw UsageError("--coarsen: --algo " + entry.name + " is certified locally uniform, and coarsening keeps the exact dual (--algo " +
                     refiners_where(true) + ")");
  const StartingMesh start = starting_mesh(in, o.exact_sites, o.quiet);
  const std::size_t vertices_in = start.domain->vertices().size();
  const auto progress = progress_printer(o.quiet);
  refiners::Run run;
  try {
    run = entry.run(*start.domain, start.field, values, budget, o.seed, progress);
  } catch (const refiners::common::DomainError& e) {
    throw UsageError(o.from.path + ": " + e.what());
  } catch (const refiners::common::FieldError& e) {
    throw UsageError(start.metric_source + ": " + e.what());
  } catch (const refiners::ParameterError& e) {
    throw UsageError(e.what());
  }
  // --coarsen and --relocate, in turn while a turn changes the mesh (at most 4 turns): a move can
  // make a removal certifiable, and a removal leaves room to move. A stopped run is neither (said).
  geometry::Mesh<double> m = run.result.mesh;
  std::size_t removed = 0, collapsed = 0, coarsen_diagrams = 0, moves = 0, relocate_diagrams = 0;
  for (int turn = 0; turn < 4 && run.result.consistent && (o.coarsen || o.relocate); ++turn) {
    const std::size_t removed_before = removed, moves_before = moves;
    if (o.coarsen) {
      Coarsened c = coarsen(m, start.field, o.collapse, o.quiet);
      removed += c.removed, collapsed += c.collapsed, coarsen_diagrams += c.diagrams, m = std::move(c.mesh);
    }
    if (o.relocate) {
      Relocated r = relocate(m, start.field, o.quiet);
      moves += r.moves, relocate_diagrams += r.diagrams, m = std::move(r.mesh);
    }
    if (!(o.coarsen && o.relocate) || (removed == removed_before && moves == moves_before)) break;
  }
  const RefinedCertificate certificate = certify_refined(entry, m, o.quiet);
  std::vector<OutputFile> files;
  std::string written;
  std::vector<std::string> paths;
  if (format) written = mesh_files(*format, m, o.output, files, paths);
  if (!o.svg.empty())
    files.push_back({o.svg, io::mesh_svg(m, entry.name + " refiner from " + o.from.path + ": " + std::to_string(m.sites.size()) + " vertices, " +
                                                (certificate.holds ? "certified" : "not certified"))});
  write_files_atomically(files);
  std::string text = "refine --from " + o.from.path + ": " + std::to_string(vertices_in) + " vertices (" +
                     std::to_string(start.boundary_vertices) + " on the boundary, " + std::to_string(start.rounded) +
                     " rounded to the nearest doubles), " + std::to_string(start.interior_segments) + " interior segments; metric " +
                     start.metric_source + "\n" + report_text(run) + (o.coarsen && !run.result.consistent ? "  not coarsened: the refiner stopped early\n"
                     : o.coarsen ? "  coarsened: " + std::to_string(removed) + " vertices removed" +
                                      (o.collapse ? " (" + std::to_string(collapsed) + " by an edge collapse: the edge's other end moved to its midpoint)" : "") +
                                      ", each kept out only when the oracle certified the rest (" + std::to_string(coarsen_diagrams) + " exact diagrams)\n"
                                : "") +
                     (o.relocate && !run.result.consistent ? "  not relocated: the refiner stopped early\n"
                      : o.relocate ? "  relocated: " + std::to_string(moves) + " moves of a vertex, each kept only when the oracle certified the moved vertices (" +
                                         std::to_string(relocate_diagrams) + " exact diagrams)\n"
                                   : "") +
                     before_after_text(start, certificate, vertices_in, removed);
  if (format) text += "  mesh: " + written + " (check it with " + check_command(entry, paths) + ")\n";
  if (!o.svg.empty()) text += "  picture: " + o.svg + "\n";
  // The product is the certificate: a run the refiner stopped early (a budget, or its subdivision
  // unable to separate sites) whose mesh the oracle certifies all the same exits 0, and says so.
  if (!run.result.consistent && certificate.holds) text += "  (the refiner stopped early; the mesh it had is certified all the same)\n";
  emit(text);
  return certificate.holds ? 0 : 1;
}

int run_refine(const RefineOptions& o) {
  const refiners::RefinerEntry* entry = refiners::find_refiner(o.algo);
  if (!entry) throw UsageError("--algo: unknown refiner " + quoted_excerpt(o.algo) + " (" + names_of(refiners::refiner_names()) + ")");
  refiners::ParameterValues values;
  for (const auto& spec : entry->parameters)
    values[spec.name] = spec.flag                              ? double(o.flags.at(spec.name))
                        : o.options.at(spec.name)->count() > 0 ? io::option_double("--" + spec.name, o.texts.at(spec.name))
                                                               : o.values.at(spec.name);
  for (const auto& [name, option] : o.options)
    if (option->count() > 0 && !values.count(name))
      throw UsageError("--" + name + " is not a parameter of --algo " + o.algo);
  if (o.seed_option->count() > 0 && !entry->seeded) throw UsageError("--seed is not a parameter of --algo " + o.algo + " (it draws no random points)");
  const refiners::common::Budget budget = budget_of(o);
  // Before the run, which may be long: the output's format and every path it is written to.
  const io::MeshFormat* format = nullptr;
  if (!o.output.empty()) {
    try {
      format = &io::mesh_format_to_write(o.output, o.output_format);
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
  }
  check_outputs({o.output, o.svg, o.json});
  if (o.from.path.empty() && (!o.from.metric.empty() || !o.from.format.empty() || !o.from.metric_format.empty() || o.exact_sites || o.coarsen ||
                              o.collapse || o.relocate))
    throw UsageError("--metric, --from-format, --metric-format, --exact-sites, --coarsen, --collapse and --relocate go with --from MESH");
  if (o.collapse && !o.coarsen) throw UsageError("--collapse: it says how --coarsen removes vertices; give --coarsen too");
  if (!o.from.path.empty()) {
    if (!o.json.empty()) throw UsageError("--json: the certificate of a 3D run (a 2D run's mesh is certified by anisocert certify --json)");
    return run_refine_from(o, *entry, values, budget, format);
  }
  if (io::names_polyhedron(o.domain)) return run_refine3(o, *entry, values, budget, format);
  if (o.domain != "square" && o.domain.find_first_of("./") == std::string::npos)
    throw UsageError("--domain " + quoted_excerpt(o.domain) + ": no such built-in domain (square; in 3D: cube, cube-cylinder) and not a file name");
  if (!o.json.empty()) throw UsageError("--json: the certificate of a 3D run (a 2D run's mesh is certified by anisocert certify --json)");
  io::DomainFile input{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}, {}};
  if (o.domain != "square") {
    try {
      input = io::read_domain_file(o.domain);
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
  }
  const fields::MetricField field = io::field_source(o.field, o.params).field;
  const auto progress = progress_printer(o.quiet);
  refiners::Run run;
  try {
    const refiners::common::Domain domain = refiners::common::Domain::from_exact(input.corners, input.points, input.interior_segments);
    run = entry->run(domain, field, values, budget, o.seed, progress);
  } catch (const refiners::common::DomainError& e) {  // e.g. a domain the refiner cannot split exactly
    throw UsageError(o.domain + ": " + e.what());
  } catch (const refiners::common::FieldError& e) {
    throw UsageError(std::string("--field: ") + e.what());
  } catch (const refiners::ParameterError& e) {
    throw UsageError(e.what());
  }
  const geometry::Mesh<double>& m = run.result.mesh;
  std::vector<OutputFile> files;
  std::string written;
  std::vector<std::string> paths;  // written, the mesh's first
  if (format) written = mesh_files(*format, m, o.output, files, paths);
  Picture drawn;
  if (!o.svg.empty()) {
    drawn = picture(*entry, m, o);
    files.push_back({o.svg, std::move(drawn.svg)});
  }
  write_files_atomically(files);
  std::string text = "refine: domain " + o.domain + ", field " + o.field + "\n" + report_text(run);
  if (format)
    text += "  mesh: " + written +
            (!run.result.consistent ? " (the run stopped early: the mesh as it stood, not necessarily a triangulation of the domain)\n"
             : !format->read        ? " (a file anisocert does not read back: write .json, .mesh or .msh to check it with " + entry->check() + ")\n"
             : !format->holds_metrics ? " (its files hold no metrics: write .json, .mesh or .msh to check it with " + entry->check() + ")\n"
                                      : " (check it with " + check_command(*entry, paths) + ")\n");
  text += drawn.line;
  emit(text);
  if (drawn.diagram)
    if (const int code = theorem7_exit_code(*drawn.diagram)) return code;
  return run.result.consistent ? 0 : 1;
}

// One line per field of a registry: "  NAME: FORMULA (parameter = default, …)".
template <class Entries>
void list_fields(std::ostringstream& o, const Entries& entries) {
  for (const auto& f : entries) {
    o << "  " << f.name << ": " << f.formula << " (";
    const char* sep = "";
    for (const auto& [name, value] : f.defaults) o << sep << name << " = " << value, sep = ", ";
    o << ")\n";
  }
}

// The help, from the registries: every refiner with its summary, every field with its parameters.
std::string description() {
  std::ostringstream o;
  o << "Anisotropic mesh refinement on a domain for a metric field.\n";
  for (const auto& e : refiners::registered_refiners()) o << "--algo " << e.name << ": " << e.summary << "\n";
  o << "Fields (--field NAME, --param name=value; formulas in docs/refiners.md):\n";
  list_fields(o, fields::builtin_fields());
  o << "  " << io::background_field_help << "\n";
  o << "3D fields (with --domain cube, cube-cylinder or a surface FILE):\n";
  list_fields(o, fields::builtin_fields3());
  o << "Exit 0 when the refiner's output condition holds (star: all stars consistent), 1 when a budget or a stall\n"
       "stopped it (the mesh written is what it had), 2 bad input, 3 the diagram --svg draws contradicts Theorem 7\n"
       "(its preconditions hold and its dual is no triangulation: a bug or a counterexample, said on standard error).";
  return o.str();
}

}  // namespace

// The refiners whose mesh is the dual of the diagram (RefinerEntry::dual_of_diagram), or the others.
std::string refiners_where(bool dual_of_diagram) {
  std::vector<std::string> names;
  for (const auto& entry : refiners::registered_refiners())
    if (entry.dual_of_diagram == dual_of_diagram) names.push_back(entry.name);
  return names_of(names);
}

void add_refine(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RefineOptions>();
  CLI::App* c = app.add_subcommand("refine", description());
  c->add_option("--algo", o->algo, "the refiner: " + names_of(refiners::refiner_names()))->capture_default_str();
  o->domain_option = c->add_option("--domain", o->domain,
                "square, or a JSON file with a \"domain\" polygon, perhaps with \"points\" and \"interior_segments\" (a PSLG;\n"
                "--algo star takes its points, not its interior segments); in 3D (--algo star): cube, cube-cylinder (UGAWG's), or a closed outward\n"
                "surface of triangles (.off, Medit .mesh/.meshb, Gmsh .msh)")
      ->capture_default_str();
  o->field_option = c->add_option("--field", o->field,
                                  "the metric field: " + names_of(fields::field_names()) + " or background:MESH[:METRIC]; in 3D: " +
                                      names_of(fields::field_names3()) + " (default ugawg-linear) or background:TETMESH[:METRIC]")
                        ->capture_default_str();
  c->add_option("--param", o->params, "a field parameter name=value (repeatable)");
  c->add_option("--from", o->from.path,
                "start from a triangle mesh someone else made (any format certify reads): its vertices are the first sites,\n"
                "the boundary of its triangles the domain (every boundary vertex a corner), its declared interior edges\n"
                "segments (not with --algo star), its metric its own (P1 over its triangles) unless --metric or --field gives\n"
                "one; the report compares before and after, and the exit is 0 only when the output is certified: the exact\n"
                "dual (--algo " + refiners_where(true) + "), locally uniform (--algo " + refiners_where(false) + ") (docs/refiners.md)");
  c->add_option("--from-format", o->from.format, "the format of --from's mesh, when its extension does not tell");
  c->add_option("--metric", o->from.metric, "--from: the mesh's per-vertex metrics in a separate file (.sol/.solb, .mtr)");
  c->add_option("--metric-format", o->from.metric_format, "--from: the metric file's format (medit, bamg)");
  c->add_flag("--exact-sites", o->exact_sites,
              "--from: refuse a vertex coordinate that is not a double (by default it is rounded to the nearest, and counted)");
  c->add_flag("--coarsen", o->coarsen,
              "--from: then remove vertices where that brings edges nearer unit length, each removal kept only when the oracle\n"
              "certifies the rest (the dual of the exact D|Ω of the remaining vertices is a triangulation; --algo " + refiners_where(true) + ")");
  c->add_flag("--collapse", o->collapse,
              "--from --coarsen: remove a vertex by collapsing its shortest edge, the other end moved to the edge's midpoint in the\n"
              "same trial, when that end is free to move (what it changes: docs/refiners.md § Coarsening)");
  c->add_flag("--relocate", o->relocate,
              "--from: then move interior vertices toward unit edges (with --coarsen, the two in turn), each move kept only\n"
              "when the oracle certifies the moved vertices (the dual of their exact D|Ω is a triangulation; --algo " + refiners_where(true) + ")");
  // A parameter several refiners share (e.g. --size) is one option: the first refiner's help and
  // default, the refiners that have it, and another's own help where it differs.
  std::map<std::string, std::pair<std::string, std::string>> help;  // name → (first help, the option's text)
  for (const auto& entry : refiners::registered_refiners())
    for (const auto& spec : entry.parameters) {
      auto& [first, text] = help[spec.name];
      if (text.empty()) {
        if (spec.flag) o->flags[spec.name] = false;
        o->values[spec.name] = spec.value;
        first = spec.help, text = spec.help + " (--algo " + entry.name;
      } else {
        text += ", " + entry.name + (spec.help == first ? "" : ": " + spec.help);
      }
    }
  for (const auto& [name, h] : help)
    o->options[name] = o->flags.count(name) ? c->add_flag("--" + name, o->flags[name], h.second + ")")
                                            : c->add_option("--" + name, o->texts[name], h.second + ")")->default_str(as_printed(o->values[name]));
  const refiners::common::Budget budget;
  c->add_option("--max-vertices", o->max_vertices, "vertex budget")->default_str(std::to_string(budget.max_vertices));
  c->add_option("--max-seconds", o->max_seconds, "time budget, read between insertions")->default_str(as_printed(budget.max_seconds));
  o->seed_option = c->add_option("--seed", o->seed, "random seed of the picking regions (--algo star)")->capture_default_str();
  c->add_option("-o,--output", o->output,
                "write the mesh with its metrics, in the format of its extension (.json, .mesh/.meshb with .sol/.solb,\n"
                ".msh Gmsh, .node/.ele/.poly; see certify --help)");
  c->add_option("--output-format", o->output_format, "the format of --output when its extension does not tell (e.g. freefem)");
  c->add_option("--svg", o->svg,
                "write a picture: --algo " + refiners_where(true) +
                    ", the exact diagram D|Ω of the final sites with its dual, computed by the oracle\n"
                    "after the run (seconds for 10k vertices, minutes for 100k); --algo " + refiners_where(false) + ", the mesh");
  c->add_option("--json", o->json, "3D: write the certificate of the run's mesh, as certify --json writes it");
  c->add_option("--threads", o->threads, "3D: threads for certifying the run's mesh (default: every core; the same verdict)");
  c->add_flag("--quiet", o->quiet, "no progress lines");
  c->callback([o, &exit_code] { exit_code = run_refine(*o); });
}

}  // namespace anisocert::cli
