// `anisocert certify MESH.json`: the exact mesh certifier (oracle/mesh_certifier.hpp). Exit 0
// when every requested check holds, 1 with witnesses when one fails, 2 for bad input.
#include "cli/output.hpp"
#include "cli/theory_command.hpp"
#include "cli/usage_error.hpp"
#include "io/site_set.hpp"
#include "oracle/certify/mesh_certifier.hpp"

#include <sstream>

namespace anisocert::cli {
namespace {

struct CertifyCommandOptions {
  std::string input, json_path, rho0, gamma0;
  std::vector<std::string> checks{"valid", "uniform"};
};

Json witnesses_json(const std::vector<oracle::MeshWitness>& ws) {
  Json out = Json::array();
  for (const auto& w : ws) out.push_back({{"vertex", w.vertex}, {"triangle", w.triangle}, {"site", w.site}, {"text", w.text}});
  return out;
}

void list_first(std::ostringstream& o, const std::vector<std::string>& lines) {
  for (std::size_t i = 0; i < lines.size() && i < 3; ++i) o << "    " << lines[i] << "\n";
  if (lines.size() > 3) o << "    … and " << lines.size() - 3 << " more\n";
}

std::vector<std::string> texts(const std::vector<oracle::MeshWitness>& ws) {
  std::vector<std::string> out;
  for (const auto& w : ws) out.push_back(w.text);
  return out;
}

int run_certify(const CertifyCommandOptions& c) {
  oracle::CertifyOptions o;
  o.valid = o.uniform = false;
  for (const std::string& k : c.checks) {
    if (k == "valid") o.valid = true;
    else if (k == "uniform") o.uniform = true;
    else throw UsageError("--checks: unknown check \"" + k + "\" (valid, uniform)");
  }
  if (!c.rho0.empty()) o.rho0 = parse_option("--rho0", c.rho0);
  if (!c.gamma0.empty()) o.gamma0 = parse_option("--gamma0", c.gamma0);
  if (o.rho0 && *o.rho0 <= 0) throw UsageError("--rho0 must be positive");
  if (o.gamma0 && *o.gamma0 < 1) throw UsageError("--gamma0 must be at least 1");
  io::SiteSet s;
  try {
    s = io::read_site_set_file(c.input);
  } catch (const io::InputError& e) {
    throw UsageError(e.what());
  }
  if (s.triangles.empty()) throw UsageError(c.input + ": triangles: a mesh needs a non-empty \"triangles\" array");
  oracle::Mesh<Rational> mesh{s.sites, {}, s.domain, s.segments, s.triangles};
  for (const auto& m : s.metrics) mesh.metrics.push_back(m.entries());
  const oracle::CertifyReport r = oracle::certify_mesh(mesh, o);
  const bool holds = r.holds(o);

  std::ostringstream text;
  text << c.input << ": " << mesh.sites.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
  if (o.valid) {
    text << "  valid (a triangulation of Ω, segments are unions of edges): " << (r.valid_holds() ? "holds" : "FAILS") << "\n";
    list_first(text, r.valid->failures);
    list_first(text, r.segment_failures);
  }
  if (o.uniform) {
    text << "  locally uniform (every triangle at v has an empty M_v-circumellipse): "
         << (r.uniform_violations.empty() ? "holds" : "FAILS") << " (" << r.incircle_tests << " exact in-circle tests, "
         << r.uniform_ties.size() << " cocircular ties)\n";
    list_first(text, texts(r.uniform_violations));
  }
  if (o.rho0) {
    text << "  radius-edge ratio ≤ " << c.rho0 << " in each vertex's metric: " << (r.rho_violations.empty() ? "holds" : "FAILS")
         << " (worst ≈ " << r.worst_rho << ", triangle " << r.worst_rho_triangle << ", vertex " << r.worst_rho_vertex << ")\n";
    list_first(text, texts(r.rho_violations));
  }
  if (o.gamma0) {
    text << "  distortion ≤ " << c.gamma0 << " between the vertices of each triangle: "
         << (r.gamma_violations.empty() ? "holds" : "FAILS") << " (worst ≈ " << r.worst_gamma << ", triangle "
         << r.worst_gamma_triangle << ")\n";
    list_first(text, texts(r.gamma_violations));
  }
  text << (holds ? "certified\n" : "not certified\n");
  if (!c.json_path.empty()) {
    Json j{{"holds", holds}, {"vertices", mesh.sites.size()}, {"triangles", mesh.triangles.size()}};
    if (o.valid)
      j["valid"] = {{"holds", r.valid_holds()}, {"checks_run", r.valid->checks_run}, {"failures", r.valid->failures},
                    {"segment_failures", r.segment_failures}};
    if (o.uniform)
      j["locally_uniform"] = {{"holds", r.uniform_violations.empty()}, {"incircle_tests", r.incircle_tests},
                              {"violations", witnesses_json(r.uniform_violations)}, {"ties", witnesses_json(r.uniform_ties)}};
    if (o.rho0)
      j["radius_edge"] = {{"threshold", c.rho0}, {"holds", r.rho_violations.empty()}, {"worst", r.worst_rho},
                          {"worst_triangle", r.worst_rho_triangle}, {"worst_vertex", r.worst_rho_vertex},
                          {"violations", witnesses_json(r.rho_violations)}};
    if (o.gamma0)
      j["distortion"] = {{"threshold", c.gamma0}, {"holds", r.gamma_violations.empty()}, {"worst", r.worst_gamma},
                         {"worst_triangle", r.worst_gamma_triangle}, {"violations", witnesses_json(r.gamma_violations)}};
    write_file_atomically(c.json_path, render(j));
  }
  emit(text.str());
  return holds ? 0 : 1;
}

}  // namespace

void add_certify_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CertifyCommandOptions>();
  CLI::App* c = app.add_subcommand(
      "certify",
      "Exact checks of a triangle mesh with per-vertex metrics (the site-set format plus \"triangles\": [[i, j, k], ...],\n"
      "counter-clockwise; numbers are read exactly from their text): valid (a triangulation of the domain, every\n"
      "segment a union of edges), locally uniform (every triangle at a vertex v has an empty circumellipse in M_v,\n"
      "ties reported apart), and, when thresholds are given, the radius-edge ratio in each vertex's metric and the\n"
      "distortion between the vertices of each triangle. Exit 0 all hold, 1 a check fails (witnesses), 2 bad input.");
  c->add_option("mesh", o->input, "the mesh (JSON)")->required();
  c->add_option("--checks", o->checks, "which of valid, uniform to run (default both)")->delimiter(',');
  c->add_option("--rho0", o->rho0, "check radius-edge ratio <= this (exact rational)");
  c->add_option("--gamma0", o->gamma0, "check distortion <= this (exact rational)");
  c->add_option("--json", o->json_path, "write the full report to this file");
  c->callback([o, &exit_code] { exit_code = run_certify(*o); });
}

}  // namespace anisocert::cli
