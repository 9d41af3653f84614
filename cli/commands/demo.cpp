// `anisocert demo`: the main job on a built-in example. First the exact diagram of 49 sites whose
// metrics follow an anisotropic shock field; then the star refiner on the unit square for a shock
// field, with parameters meeting every decided condition of LU Theorem 4.5, and the exact
// certifier on its mesh.
#include "cli/diagram_job.hpp"
#include "cli/output.hpp"
#include "io/reports/certify_report.hpp"
#include "cli/reports/refine_report.hpp"
#include "fields/registry.hpp"
#include "io/svg/mesh_svg.hpp"
#include "refiners/registry.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>

namespace anisocert::cli {
namespace {

// The demo's anisotropic field: the built-in shock field (fields/shock.cpp) with δ = 0.25, h = 1,
// α = 9: first eigen-direction along ∇f, lengths across the level lines of f shrinking by up to
// 10; entries rounded to 2 decimals, exact as given. Sites on a jittered 7 × 7 grid.
geometry::Mesh<Rational> demo_input() {
  geometry::Mesh<Rational> in;
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

// The demo's second half: its summary, and the picture for `svg_path`. Its parameters meet every
// condition of LU Theorem 4.5 that theory/ decides ((1 − δ)³ρ₀ > 2γ₀³ needs ρ₀ > 4.74 at γ₀ = 1.2,
// δ = 0.1).
std::string refine_and_certify(const std::string& svg_path, bool quiet, std::vector<OutputFile>& files) {
  const refiners::RefinerEntry& star = *refiners::find_refiner("star");
  refiners::ParameterValues values = star.defaults();
  values["rho0"] = 5, values["beta"] = 5, values["gamma0"] = 1.2;
  refiners::common::Budget budget;
  budget.max_seconds = 60;
  const auto field = fields::make_field("shock", {{"h", 0.05}, {"alpha", 3}});
  const refiners::Run run =
      star.run(refiners::common::Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), field, values, budget, 1, progress_printer(quiet));
  const geometry::Mesh<double>& mesh = run.result.mesh;
  oracle::CertifyOptions o;
  o.rho0 = rational_from_double(values["rho0"]), o.gamma0 = rational_from_double(values["gamma0"]);
  const geometry::Mesh<Rational> exact = geometry::exact(mesh);
  io::BoundTexts bounds;
  bounds.rho0 = as_printed(values["rho0"]), bounds.gamma0 = as_printed(values["gamma0"]);
  const io::CertifyVerdict verdict = io::certify_verdict(oracle::certify_mesh(exact, o), o, exact, bounds);
  files.push_back({svg_path, io::mesh_svg(mesh, "star refiner, shock field: " + std::to_string(mesh.sites.size()) +
                                                    " vertices, " + (verdict.holds ? "certified" : "not certified"))});
  return "refine: the unit square, field shock (h = 0.05, alpha = 3, delta = 0.6)\n" + report_text(run) + io::one_line(verdict) +
         "  picture: " + svg_path + "\n";
}

}  // namespace

void add_demo(CLI::App& app, int& exit_code) {
  struct Options {
    DiagramOutputs outputs{"", "anisocert-demo.svg"};
    std::string mesh_svg_path = "anisocert-demo-mesh.svg";
  };
  auto o = std::make_shared<Options>();
  CLI::App* c = app.add_subcommand(
      "demo",
      "The diagram of a built-in example: 49 sites in the unit square whose metrics follow the shock field\n"
      "f = tanh((2x − sin 5y)/0.25) (first eigen-direction along ∇f, anisotropy up to 10:1). Prints the\n"
      "summary and writes the picture; then refines the unit square for a shock field with the star refiner and\n"
      "certifies the mesh exactly.");
  c->add_option("--svg", o->outputs.svg_path, "where to write the picture")->capture_default_str();
  c->add_option("--json", o->outputs.json_path, "also write the diagram as JSON to this file");
  c->add_flag("--quiet", o->outputs.quiet, "no progress lines on standard error");
  c->add_option("--mesh-svg", o->mesh_svg_path, "where to write the picture of the refined mesh")->capture_default_str();
  c->callback([o, &exit_code] {
    DiagramJob job = diagram_job(demo_input(), "demo", o->outputs);
    if (job.exit_code == 0) job.text += refine_and_certify(o->mesh_svg_path, o->outputs.quiet, job.files);
    write_files_atomically(job.files);
    emit(job.text);
    exit_code = job.exit_code;
  });
}

}  // namespace anisocert::cli
