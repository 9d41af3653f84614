#include "cli/command.hpp"

namespace anisocert::cli {

void add_theory(CLI::App&, int&);
void add_theory_chi(CLI::App&, int&);
void add_theory_bwy(CLI::App&, int&);
void add_theory_lu(CLI::App&, int&);
void add_conics(CLI::App&, int&);
void add_diagram(CLI::App&, int&);
void add_demo(CLI::App&, int&);
void add_certify(CLI::App&, int&);
void add_refine(CLI::App&, int&);
void add_metric(CLI::App&, int&);
void add_dual(CLI::App&, int&);

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"theory", add_theory},
      {"conics", add_conics},
      {"diagram", add_diagram},
      {"demo", add_demo},
      {"certify", add_certify},
      {"dual", add_dual},
      {"refine", add_refine},
      {"metric", add_metric},
  };
  return table;
}

const std::vector<Command>& theory_commands() {
  static const std::vector<Command> table = {
      {"chi", add_theory_chi},
      {"bwy", add_theory_bwy},
      {"lu", add_theory_lu},
  };
  return table;
}

}  // namespace anisocert::cli
