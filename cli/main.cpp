// anisocert: exact verification of anisotropic Voronoi diagrams and meshes.
// Exit codes (DESIGN.md § Command line): 0 holds, 1 does not hold, 2 bad input or usage,
// 3 internal error (a bug: a check of our own output failed).

#include "cli/command.hpp"
#include "cli/usage_error.hpp"
#include "io/input_error.hpp"
#include "numbers/excerpt.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{
      "anisocert: exact certification of anisotropic Voronoi diagrams and anisotropic meshes\n"
      "(Labelle & Shewchuk 2003; Boissonnat, Wormser & Yvinec). Exit codes: 0 holds, 1 does not hold,\n"
      "2 bad input or usage, 3 internal error.",
      "anisocert"};
  app.require_subcommand(1);
  int exit_code = 0;
  for (const anisocert::cli::Command& c : anisocert::cli::commands()) c.add(app, exit_code);
  try {
    const auto known = app.get_subcommands([&](CLI::App* s) { return argc > 1 && s->check_name(argv[1]); });
    if (argc > 1 && argv[1][0] != '-' && known.empty())
      throw anisocert::cli::UsageError("unknown command " + anisocert::quoted_excerpt(argv[1]) + " (see anisocert --help)");
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, for the command it follows
    // CLI11's message may quote an argument: one line of it, at most a few hundred characters.
    std::cerr << "anisocert: " << anisocert::excerpt(e.what(), 300) << " (see anisocert --help)\n";
    return 2;
  } catch (const anisocert::cli::UsageError& e) {
    std::cerr << "anisocert: " << e.what() << "\n";
    return 2;
  } catch (const anisocert::io::InputError& e) {  // a file or a --field the io layer refused
    std::cerr << "anisocert: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "anisocert: internal error: " << e.what() << "\n";
    return 3;
  }
  return exit_code;
}
