#pragma once
// A command of `anisocert`: its name and how it registers itself on its parent (options, help and
// a callback that stores its exit code: 0 holds or computed, 1 a verdict that does not hold; bad
// input throws UsageError). Each command is one file of cli/commands/; command_table.cpp lists
// them, one line each.
#include <CLI/CLI.hpp>

#include <vector>

namespace anisocert::cli {

struct Command {
  const char* name;
  void (*add)(CLI::App& parent, int& exit_code);
};

// The commands of `anisocert`, and those of `anisocert theory`.
const std::vector<Command>& commands();
const std::vector<Command>& theory_commands();

}  // namespace anisocert::cli
