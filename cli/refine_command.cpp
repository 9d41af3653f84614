// `anisocert refine --algo star`: the locally uniform star refiner (refiners/star/) on a domain and
// a built-in metric field; writes the mesh for `anisocert certify`, Medit .mesh/.sol and SVG.
#include "cli/output.hpp"
#include "cli/refine_command.hpp"
#include "cli/theory_command.hpp"
#include "cli/usage_error.hpp"
#include "io/site_set.hpp"
#include "theory/lu_theorem45.hpp"

#include <sstream>

namespace anisocert::cli {

using refiners::star::RefineParameters;
using refiners::star::RefineResult;

std::string lu_conditions_text(const RefineParameters& p) {
  const theory::LuConditions c = theory::lu_t45_conditions(
      {rational_from_double(p.rho0), rational_from_double(p.gamma0), rational_from_double(p.delta), rational_from_double(p.beta)});
  std::ostringstream o;
  o << "  LU Theorem 4.5 conditions (decided exactly): ρ₀ > 2 " << (c.rho0_above_2 ? "yes" : "no") << ", (1−δ)³ρ₀ > 2 "
    << (c.delta_rho0 ? "yes" : "no") << ", (1−δ)³β > 2 " << (c.delta_beta ? "yes" : "no") << ", (1−δ)³ρ₀ > 2γ₀³ "
    << (c.lemma43 ? "yes" : "no") << ", (1−δ)³β > 2γ₀³ " << (c.lemma44 ? "yes" : "no") << "\n";
  return o.str();
}

std::string refine_summary(const RefineResult& r, const RefineParameters& p) {
  std::ostringstream o;
  o << "  star refiner: " << r.sites.size() << " vertices, " << r.triangles.size() << " triangles in " << r.seconds << " s ("
    << static_cast<long>(r.sites.size() / std::max(r.seconds, 1e-9)) << " vertices/s)\n"
    << "  stopped: " << r.stop_reason;
  if (!r.consistent) o << "; rule still firing: " << refiners::star::rule_name(r.last_rule) << "; inconsistent star triangles: " << r.inconsistent_triangles;
  o << "\n  LU Lemma 4.1 (boundary angles > 90° in the metric): ";
  if (r.acute_corners.empty()) o << "holds at every corner";
  else {
    o << "fails at corner(s)";
    for (int k : r.acute_corners) o << " " << k;
    o << " (encroachment there may not end)";
  }
  o << "\n  Pick_valid: " << r.picks_rejected << " picked points discarded as γ₀-cocircular, " << r.picks_exhausted
    << " of " << r.refinements << " refinements kept a forbidden point after " << p.pick_attempts << " discards";
  if (p.pick_attempts > 0 && 2 * r.picks_exhausted > r.refinements)
    o << " (most: at this γ₀ the forbidden set covers most of each picking region; LU Lemma 3.15 needs γ₀ close to 1)";
  o << "\n  insertions by rule:";
  for (int k = 1; k <= 5; ++k) o << " " << refiners::star::rule_name(k) << " " << r.rule_counts[k] << (k < 5 ? "," : "\n");
  o << "  parameters: ρ₀ = " << p.rho0 << ", γ₀ = " << p.gamma0 << ", δ = " << p.delta << ", β = " << p.beta << ", size = " << p.size
    << "\n" << lu_conditions_text(p);
  return o.str();
}

io::MeshData mesh_data(const RefineResult& r) { return {r.sites, r.metrics, r.domain, r.segments, r.triangles}; }

namespace {

struct RefineOptions {
  std::string algo = "star", domain = "square", field = "shock", output, svg, medit;
  std::vector<std::string> params;
  RefineParameters p;
  bool quiet = false;
};

int run_refine(const RefineOptions& o) {
  if (o.algo != "star") throw UsageError("--algo: only \"star\" is implemented (LU star sets)");
  std::vector<predicates::Point2<double>> domain;
  if (o.domain == "square") {
    domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  } else {
    try {
      for (const auto& q : io::read_domain_file(o.domain)) {
        const double x = q.x.convert_to<double>(), y = q.y.convert_to<double>();
        if (Rational(x) != q.x || Rational(y) != q.y)
          throw UsageError(o.domain + ": domain vertex (" + to_exact_string(q.x) + ", " + to_exact_string(q.y) +
                           ") is not a double; the refiner works in floating point");
        domain.push_back({x, y});
      }
    } catch (const io::InputError& e) {
      throw UsageError(e.what());
    }
  }
  std::map<std::string, double> params;
  for (const std::string& kv : o.params) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw UsageError("--param \"" + kv + "\": expected name=value");
    params[kv.substr(0, eq)] = parse_option("--param " + kv.substr(0, eq), kv.substr(eq + 1)).convert_to<double>();
  }
  refiners::star::MetricField field;
  try {
    field = refiners::star::make_field(o.field, params);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--field: ") + e.what());
  }
  if (!(o.p.gamma0 > 1) || !(o.p.rho0 > 0) || !(o.p.delta > 0 && o.p.delta < 1) || !(o.p.beta > 0) || !(o.p.size > 0))
    throw UsageError("parameters out of range: need γ₀ > 1, ρ₀ > 0, 0 < δ < 1, β > 0, size > 0");
  const auto progress = progress_printer(o.quiet);
  RefineResult r;
  try {
    r = refiners::star::refine_star(domain, field, o.p, progress);
  } catch (const std::invalid_argument& e) {  // a domain the refiner cannot split exactly
    throw UsageError(o.domain + ": " + e.what());
  }
  const io::MeshData m = mesh_data(r);
  if (!o.output.empty()) write_file_atomically(o.output, io::mesh_json(m));
  if (!o.svg.empty()) write_file_atomically(o.svg, io::mesh_svg(m, "star refiner, field " + o.field + ": " + std::to_string(r.sites.size()) + " vertices"));
  if (!o.medit.empty()) {
    write_file_atomically(o.medit + ".mesh", io::medit_mesh(m));
    write_file_atomically(o.medit + ".sol", io::medit_sol(m));
  }
  std::string text = "refine: domain " + o.domain + ", field " + o.field + "\n" + refine_summary(r, o.p);
  if (!o.output.empty()) text += "  mesh: " + o.output + " (check it with anisocert certify)\n";
  emit(text);
  return r.consistent ? 0 : 1;
}

}  // namespace

void add_refine_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RefineOptions>();
  CLI::App* c = app.add_subcommand(
      "refine",
      "Anisotropic mesh refinement. --algo star: locally uniform star sets (Boissonnat, Wormser & Yvinec), rules\n"
      "(1) encroachment, (2) distortion, (3) radius-edge ratio, (4) size, (5) inconsistency. Fields (--field):\n"
      "constant (m11, m12, m22), linear (hx, h0), shock (delta, h, alpha), radial (cx, cy, R, delta, h, alpha);\n"
      "formulas in docs/refiners.md. Exit 0 when all stars are consistent, 1 when a budget stopped it (the mesh\n"
      "written is what it had), 2 bad input.");
  c->add_option("--algo", o->algo, "the refiner (star)")->capture_default_str();
  c->add_option("--domain", o->domain, "square, or a JSON file with a \"domain\" polygon")->capture_default_str();
  c->add_option("--field", o->field, "constant, linear, shock or radial")->capture_default_str();
  c->add_option("--param", o->params, "a field parameter name=value (repeatable)");
  c->add_option("--rho0", o->p.rho0, "radius-edge ratio bound ρ₀")->capture_default_str();
  c->add_option("--gamma0", o->p.gamma0, "distortion bound γ₀")->capture_default_str();
  c->add_option("--delta", o->p.delta, "picking-region ratio δ")->capture_default_str();
  c->add_option("--beta", o->p.beta, "cosphericity radius ratio β (checked against Theorem 4.5)")->capture_default_str();
  c->add_option("--size", o->p.size, "largest circumradius in the metric")->capture_default_str();
  c->add_option("--pick-attempts", o->p.pick_attempts,
                "Pick_valid: picked points that may be discarded as γ₀-cocircular before one is kept (0: no test)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  c->add_option("--max-vertices", o->p.max_vertices, "vertex budget")->capture_default_str();
  c->add_option("--max-seconds", o->p.max_seconds, "time budget")->capture_default_str();
  c->add_option("--seed", o->p.seed, "random seed of the picking regions")->capture_default_str();
  c->add_option("-o,--output", o->output, "write the mesh (JSON for anisocert certify)");
  c->add_option("--svg", o->svg, "write a picture of the mesh");
  c->add_option("--medit", o->medit, "write BASE.mesh and BASE.sol (Medit, per-vertex metric)");
  c->add_flag("--quiet", o->quiet, "no progress lines");
  c->callback([o, &exit_code] { exit_code = run_refine(*o); });
}

}  // namespace anisocert::cli
