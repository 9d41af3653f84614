// `anisocert diagram IN.json`: the exact anisotropic Voronoi diagram restricted to the domain
// (oracle/diagram/diagram.hpp), its wedges, orphans, dual and Theorem 7 verdict.
#include "cli/diagram_job.hpp"
#include "cli/output.hpp"
#include "cli/usage_error.hpp"
#include "io/mesh_json.hpp"

#include <CLI/CLI.hpp>

#include <memory>

namespace anisocert::cli {

void add_diagram(CLI::App& app, int& exit_code) {
  struct Options {
    std::string input;
    DiagramOutputs outputs;
  };
  auto o = std::make_shared<Options>();
  CLI::App* c = app.add_subcommand(
      "diagram",
      "The exact anisotropic Voronoi diagram (Labelle–Shewchuk) of the sites of IN.json restricted to its domain:\n"
      "vertices, arcs, faces and orphans, wedges with exact witnesses, the dual and whether it triangulates the\n"
      "domain, and the Theorem 7 verdict. Prints a summary; exit 0 (the diagram is an answer, not a verdict),\n"
      "2 for bad input, 3 if Theorem 7's preconditions hold but its conclusion fails (a bug or a counterexample).\n"
      "Input format: docs/oracle.md (DESIGN.md § Command line and files).");
  c->add_option("input", o->input, "the site set (JSON)")->required();
  c->add_option("--json", o->outputs.json_path, "write the whole diagram as JSON to this file (fields: docs/oracle.md)");
  c->add_option("--svg", o->outputs.svg_path, "write a picture of the diagram to this file");
  c->add_flag("--quiet", o->outputs.quiet, "no progress lines on standard error");
  c->add_flag("--exact-only", o->outputs.exact_only,
              "build every point with exact arithmetic (no interval filters first); same answers, slower");
  c->add_option("--threads", o->outputs.threads, "threads for candidate triples and pairs (default: every core)")
      ->check(CLI::Range(1, 1024));
  c->callback([o, &exit_code] {
    check_outputs({o->outputs.json_path, o->outputs.svg_path});  // before the diagram, which can take minutes
    geometry::Mesh<Rational> in;
    try {
      in = io::read_mesh_json_file(o->input);
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
    const DiagramJob job = diagram_job(in, o->input, o->outputs);
    write_files_atomically(job.files);
    emit(job.text);
    exit_code = job.exit_code;
  });
}

}  // namespace anisocert::cli
