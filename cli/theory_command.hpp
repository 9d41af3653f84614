#pragma once
// `anisocert theory` and its subcommands `chi`, `bwy`, `lu`: the papers' constants and
// bounds as certified intervals (theory/).

#include <CLI/CLI.hpp>

namespace anisocert::cli {

// Registers the commands on `app`; the one that runs stores its exit code in `exit_code`
// (0: holds / computed, 1: a verdict that does not hold). Bad input throws UsageError.
void add_theory_command(CLI::App& app, int& exit_code);

void add_theory_chi_command(CLI::App& theory, int& exit_code);
void add_theory_bwy_command(CLI::App& theory, int& exit_code);
void add_theory_lu_command(CLI::App& theory, int& exit_code);

// `anisocert conics` (oracle/conic_intersection).
void add_conics_command(CLI::App& app, int& exit_code);
// `anisocert diagram IN.json` and `anisocert demo` (diagram_command.cpp).
void add_diagram_command(CLI::App& app, int& exit_code);
void add_demo_command(CLI::App& app, int& exit_code);
// `anisocert certify MESH.json` (certify_command.cpp).
void add_certify_command(CLI::App& app, int& exit_code);
// `anisocert refine` (refine_command.cpp).
void add_refine_command(CLI::App& app, int& exit_code);

}  // namespace anisocert::cli
