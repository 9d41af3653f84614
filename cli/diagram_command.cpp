// `anisocert diagram IN.json`: the exact anisotropic Voronoi diagram restricted to the domain
// (oracle/diagram.hpp), its wedges, orphans, dual and Theorem 7 verdict; and `anisocert demo`,
// the same on a built-in example whose metrics come from an anisotropic shock field.
#include "cli/output.hpp"
#include "cli/refine_command.hpp"
#include "cli/theory_command.hpp"
#include "cli/usage_error.hpp"
#include "io/diagram_json.hpp"
#include "io/diagram_svg.hpp"
#include "io/site_set.hpp"
#include "fields/registry.hpp"
#include "oracle/certify/mesh_certifier.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

namespace anisocert::cli {
namespace {

struct DiagramOptions {
  std::string input;
  std::string json_path, svg_path, mesh_svg_path = "anisocert-demo-mesh.svg";
  bool quiet = false;
};

oracle::Mesh<Rational> diagram_input(const io::SiteSet& s) {
  oracle::Mesh<Rational> in;
  in.sites = s.sites;
  for (const auto& m : s.metrics) in.metrics.push_back(m.entries());
  in.domain = s.domain;
  return in;
}

std::string summary(const oracle::Diagram& d, const std::string& name) {
  const io::DiagramCounts c = io::diagram_counts(d);
  std::ostringstream o;
  o << name << ": " << d.input.sites.size() << " sites, domain with " << d.input.domain.size() << " corners\n"
    << "  Voronoi vertices " << c.voronoi_vertices << ", arcs " << c.arcs << ", faces " << c.faces << ", orphans "
    << c.orphans << ", wedge violations " << c.wedge_violations << "\n";
  std::size_t closed = 0, cut = 0, high = 0;
  for (const auto& a : d.arcs) closed += a.closed ? 1 : 0, cut += a.cut_by_edges.empty() ? 0 : 1;
  for (const auto& n : d.nodes) high += n.sites.size() > 3 ? 1 : 0;
  o << "  closed arcs " << closed << ", arcs cut by ∂Ω " << cut << ", vertices with more than three owners " << high << "\n";
  std::size_t listed = 0;
  for (std::size_t i = 0; i < d.faces.size(); ++i)
    if (d.faces[i].orphan && listed++ < 5) o << "  orphan: face " << i << " of site " << d.faces[i].site << "\n";
  if (listed > 5) o << "  … and " << listed - 5 << " more orphans (all in --json)\n";
  o << "  dual: " << d.dual_triangles.size() << " triangles, " << d.dual_polygons.size() << " polygons; "
    << (d.dual_check.is_triangulation ? "a triangulation of Ω (checked exactly)" : "not a triangulation of Ω") << "\n";
  for (std::size_t i = 0; i < d.dual_check.failures.size() && i < 3; ++i) o << "    " << d.dual_check.failures[i] << "\n";
  if (d.dual_check.failures.size() > 3) o << "    … and " << d.dual_check.failures.size() - 3 << " more\n";
  o << "  Theorem 7 preconditions: " << (d.theorem7.preconditions_hold ? "hold" : "do not hold") << "\n";
  for (std::size_t i = 0; i < d.theorem7.reasons.size() && i < 3; ++i) o << "    " << d.theorem7.reasons[i] << "\n";
  if (d.theorem7.reasons.size() > 3) o << "    … and " << d.theorem7.reasons.size() - 3 << " more\n";
  if (d.theorem7.preconditions_hold)
    o << "  Theorem 7 conclusion: " << (d.dual_check.is_triangulation ? "confirmed" : "CONTRADICTED") << "\n";
  o << "  time: candidates " << d.stats.seconds_candidates << " s, vertices " << d.stats.seconds_vertices << " s, arcs "
    << d.stats.seconds_arcs << " s, faces " << d.stats.seconds_faces << " s, dual " << d.stats.seconds_dual << " s\n";
  return o.str();
}

int run(const oracle::Mesh<Rational>& in, const std::string& name, const DiagramOptions& o) {
  const auto progress = progress_printer(o.quiet);
  oracle::Diagram d;
  try {
    d = oracle::compute_diagram(in, progress);
  } catch (const std::domain_error& e) {  // a degenerate input the oracle declines, named
    throw UsageError(name + ": " + e.what());
  }
  std::string json, svg;
  if (!o.json_path.empty()) json = io::diagram_json(d).dump(1) + "\n";
  if (!o.svg_path.empty()) svg = io::diagram_svg(d);
  if (!o.json_path.empty()) write_file_atomically(o.json_path, json);
  if (!o.svg_path.empty()) write_file_atomically(o.svg_path, svg);
  std::string text = summary(d, name);
  if (!o.svg_path.empty()) text += "  picture: " + o.svg_path + "\n";
  if (d.theorem7.disagreement) {
    std::cerr << "anisocert: THEOREM 7 DISAGREEMENT: its preconditions hold but the dual is not a triangulation of Ω.\n"
                 "This is a bug in the oracle or a counterexample to LS Theorem 7; please report the input.\n";
    emit(text);
    return 3;
  }
  emit(text);
  return 0;
}

// The demo's anisotropic field: the built-in shock field (fields/shock.cpp) with
// δ = 0.25, h = 1, α = 9: first eigen-direction along ∇f, lengths across the level lines of f
// shrinking by up to 10; entries rounded to 2 decimals, exact as given.
oracle::Mesh<Rational> demo_input() {
  oracle::Mesh<Rational> in;
  in.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto field = fields::make_field("shock", {{"delta", 0.25}, {"h", 1}, {"alpha", 9}});
  unsigned state = 12345;
  auto jitter = [&] {  // a fixed linear congruential sequence: the same example every time
    state = state * 1103515245u + 12345u;
    return static_cast<int>((state >> 16) % 61) - 30;  // −30 … 30 thousandths
  };
  auto q = [](double v) { return Rational(static_cast<long>(std::lround(v * 100)), 100); };
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const Rational x = Rational(1000 * (2 * i + 1) / 14 + jitter(), 1000);
      const Rational y = Rational(1000 * (2 * j + 1) / 14 + jitter(), 1000);
      const auto M = field.at(x.convert_to<double>(), y.convert_to<double>());
      in.sites.push_back({x, y});
      in.metrics.push_back({q(M.m11), q(M.m12), q(M.m22)});
    }
  return in;
}

}  // namespace

void add_diagram_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DiagramOptions>();
  CLI::App* c = app.add_subcommand(
      "diagram",
      "The exact anisotropic Voronoi diagram (Labelle–Shewchuk) of the sites of IN.json restricted to its domain:\n"
      "vertices, arcs, faces and orphans, wedges with exact witnesses, the dual and whether it triangulates the\n"
      "domain, and the Theorem 7 verdict. Prints a summary; exit 0 (the diagram is an answer, not a verdict),\n"
      "2 for bad input, 3 if Theorem 7's preconditions hold but its conclusion fails (a bug or a counterexample).\n"
      "Input format: docs/oracle.md (DESIGN.md § Command line and files).");
  c->add_option("input", o->input, "the site set (JSON)")->required();
  c->add_option("--json", o->json_path, "write the whole diagram as JSON to this file (fields: docs/oracle.md)");
  c->add_option("--svg", o->svg_path, "write a picture of the diagram to this file");
  c->add_flag("--quiet", o->quiet, "no progress lines on standard error");
  c->callback([o, &exit_code] {
    io::SiteSet s;
    try {
      s = io::read_site_set_file(o->input);
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
    exit_code = run(diagram_input(s), o->input, *o);
  });
}

// The demo's second half: the star refiner on the unit square with a shock field, and the exact
// certifier on its output. Its parameters meet every condition of LU Theorem 4.5 that theory/
// decides ((1 − δ)³ρ₀ > 2γ₀³ needs ρ₀ > 4.74 at γ₀ = 1.2, δ = 0.1).
std::string refine_and_certify(const std::string& svg_path, bool quiet) {
  const refiners::RefinerEntry& star = *refiners::find_refiner("star");
  refiners::ParameterValues values;
  for (const auto& spec : star.parameters) values[spec.name] = spec.value;
  values["rho0"] = 5, values["beta"] = 5, values["gamma0"] = 1.2;
  refiners::common::Budget budget;
  budget.max_seconds = 60;
  const auto field = fields::make_field("shock", {{"h", 0.05}, {"alpha", 3}});
  const refiners::Run run =
      star.run(refiners::common::Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), field, values, budget, 1, progress_printer(quiet));
  const io::MeshData& data = run.result.mesh;
  oracle::CertifyOptions o;
  o.rho0 = rational_from_double(values["rho0"]), o.gamma0 = rational_from_double(values["gamma0"]);
  const oracle::CertifyReport c = oracle::certify_mesh(geometry::exact(data), o);
  std::ostringstream out;
  out << "refine: the unit square, field shock (h = 0.05, alpha = 3, delta = 0.6)\n" << report_text(run)
      << "certify (exact): valid " << (c.valid_holds() ? "holds" : "FAILS") << ", locally uniform "
      << (c.uniform_violations.empty() ? "holds" : "FAILS") << " (" << c.uniform_ties.size() << " ties), radius-edge ≤ "
      << values["rho0"] << " " << (c.rho_violations.empty() ? "holds" : "FAILS") << ", distortion ≤ " << values["gamma0"] << " "
      << (c.gamma_violations.empty() ? "holds" : "FAILS") << ": " << (c.holds(o) ? "certified" : "NOT certified") << "\n";
  write_file_atomically(svg_path, io::mesh_svg(data, "star refiner, shock field: " + std::to_string(data.sites.size()) +
                                                                 " vertices, " + (c.holds(o) ? "certified" : "not certified")));
  out << "  picture: " << svg_path << "\n";
  return out.str();
}

void add_demo_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DiagramOptions>();
  o->svg_path = "anisocert-demo.svg";
  CLI::App* c = app.add_subcommand(
      "demo",
      "The diagram of a built-in example: 49 sites in the unit square whose metrics follow the shock field\n"
      "f = tanh((2x − sin 5y)/0.25) (first eigen-direction along ∇f, anisotropy up to 10:1). Prints the\n"
      "summary and writes the picture; then refines the unit square for a shock field with the star refiner and\n"
      "certifies the mesh exactly.");
  c->add_option("--svg", o->svg_path, "where to write the picture")->capture_default_str();
  c->add_option("--json", o->json_path, "also write the diagram as JSON to this file");
  c->add_flag("--quiet", o->quiet, "no progress lines on standard error");
  c->add_option("--mesh-svg", o->mesh_svg_path, "where to write the picture of the refined mesh")->capture_default_str();
  c->callback([o, &exit_code] {
    exit_code = run(demo_input(), "demo", *o);
    if (exit_code == 0) emit(refine_and_certify(o->mesh_svg_path, o->quiet));
  });
}

}  // namespace anisocert::cli
