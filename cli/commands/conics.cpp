// `anisocert conics`: the real common points of two conics, exactly (oracle/), so that a user
// can check another library's conic intersections.

#include "cli/theory_output.hpp"
#include "cli/usage_error.hpp"
#include "oracle/algebraic/conic_intersection.hpp"

#include <sstream>

namespace anisocert::cli {
namespace {

struct ConicsOptions {
  std::vector<std::string> coefficients;
  OutputOptions output;
};

oracle::Conic conic_from(const std::vector<std::string>& text, std::size_t first, const char* name) {
  Rational c[6];
  for (std::size_t i = 0; i < 6; ++i) c[i] = parse_option(std::string(name) + std::to_string(i + 1), text[first + i]);
  return {c[0], c[1], c[2], c[3], c[4], c[5]};
}

int run_conics(const ConicsOptions& o) {
  if (o.coefficients.size() != 12)
    throw UsageError("conics needs 12 coefficients (a b c d e f of A, then of B), got " +
                     std::to_string(o.coefficients.size()));
  const oracle::Conic A = conic_from(o.coefficients, 0, "A"), B = conic_from(o.coefficients, 6, "B");
  oracle::ConicIntersection r;
  try {
    r = oracle::intersect(A, B);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const int n = o.output.digits;
  Json points = Json::array();
  std::ostringstream text;
  text << "A: a x² + b xy + c y² + d x + e y + f with (a..f) = (";
  for (int i = 0; i < 6; ++i) text << (i ? ", " : "") << to_exact_string(parse_rational(o.coefficients[i]));
  text << ")\nB: (";
  for (int i = 6; i < 12; ++i) text << (i > 6 ? ", " : "") << to_exact_string(parse_rational(o.coefficients[i]));
  text << ")\n";
  if (r.shared_component) text << "The conics share a component: infinitely many common points.\n";
  else text << r.points.size() << " real common point(s), exact; coordinates correctly rounded to " << n << " digits:\n";
  for (const oracle::IntersectionPoint& p : r.points) {
    const std::string x = p.point.x_decimal(n), y = p.point.y_decimal(n);
    points.push_back(Json{{"x", x}, {"y", y}, {"multiplicity", p.multiplicity}});
    text << "  (" << x << ", " << y << ")  multiplicity " << p.multiplicity << "\n";
  }
  emit(o.output.json ? render(Json{{"shared_component", r.shared_component}, {"points", points}}) : text.str());
  return 0;
}

}  // namespace

void add_conics(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ConicsOptions>();
  CLI::App* conics = app.add_subcommand(
      "conics",
      "The real common points of the conics A: a x² + b xy + c y² + d x + e y + f = 0 and B, exactly, with their\n"
      "intersection multiplicities, sorted by x then y; or that they share a component. Coefficients are exact\n"
      "decimals or fractions: anisocert conics A1 .. A6 B1 .. B6.");
  conics->add_option("coefficients", o->coefficients, "a b c d e f of A, then of B (12 numbers)")->required();
  add_output_options(*conics, o->output);
  o->output.digits = 30;
  conics->get_option("--digits")->default_val(30)->check(CLI::Range(1, 2000));
  conics->callback([o, &exit_code] { exit_code = run_conics(*o); });
}

}  // namespace anisocert::cli
