#include "cli/reports/certify_report.hpp"

#include <sstream>

namespace anisocert::cli {
namespace {

Json witnesses_json(const std::vector<oracle::MeshWitness>& ws) {
  Json out = Json::array();
  for (const auto& w : ws) out.push_back({{"vertex", w.vertex}, {"triangle", w.triangle}, {"site", w.site}, {"text", w.text}});
  return out;
}

std::vector<std::string> texts(const std::vector<oracle::MeshWitness>& ws) {
  std::vector<std::string> out;
  for (const auto& w : ws) out.push_back(w.text);
  return out;
}

const char* verdict(bool holds) { return holds ? "holds" : "FAILS"; }

}  // namespace

CertifyVerdict certify_verdict(const oracle::CertifyReport& r, const oracle::CertifyOptions& o,
                               const geometry::Mesh<Rational>& mesh, const std::string& rho0_text,
                               const std::string& gamma0_text) {
  CertifyVerdict v;
  v.vertices = mesh.sites.size(), v.triangles = mesh.triangles.size(), v.holds = r.holds(o);
  if (o.valid)
    v.checks.push_back({"valid", "valid (a triangulation of Ω, segments are unions of edges)", "valid", r.valid_holds(), "", "",
                        {r.valid->failures, r.segment_failures},
                        {{"holds", r.valid_holds()}, {"checks_run", r.valid->checks_run}, {"failures", r.valid->failures},
                         {"segment_failures", r.segment_failures}}});
  if (o.uniform) {
    const bool holds = r.uniform_violations.empty();
    v.checks.push_back({"locally_uniform", "locally uniform (every triangle at v has an empty M_v-circumellipse)",
                        "locally uniform", holds,
                        " (" + std::to_string(r.incircle_tests) + " exact in-circle tests, " +
                            std::to_string(r.uniform_ties.size()) + " cocircular ties)",
                        " (" + std::to_string(r.uniform_ties.size()) + " ties)", {texts(r.uniform_violations)},
                        {{"holds", holds}, {"incircle_tests", r.incircle_tests},
                         {"violations", witnesses_json(r.uniform_violations)}, {"ties", witnesses_json(r.uniform_ties)}}});
  }
  if (o.rho0) {
    const bool holds = r.rho_violations.empty();
    v.checks.push_back({"radius_edge", "radius-edge ratio ≤ " + rho0_text + " in each vertex's metric", "radius-edge ≤ " + rho0_text,
                        holds,
                        " (worst ≈ " + as_printed(r.worst_rho) + ", triangle " + std::to_string(r.worst_rho_triangle) + ", vertex " +
                            std::to_string(r.worst_rho_vertex) + ")",
                        "", {texts(r.rho_violations)},
                        {{"threshold", rho0_text}, {"holds", holds}, {"worst", r.worst_rho},
                         {"worst_triangle", r.worst_rho_triangle}, {"worst_vertex", r.worst_rho_vertex},
                         {"violations", witnesses_json(r.rho_violations)}}});
  }
  if (o.gamma0) {
    const bool holds = r.gamma_violations.empty();
    v.checks.push_back({"distortion", "distortion ≤ " + gamma0_text + " between the vertices of each triangle",
                        "distortion ≤ " + gamma0_text, holds,
                        " (worst ≈ " + as_printed(r.worst_gamma) + ", triangle " + std::to_string(r.worst_gamma_triangle) + ")", "",
                        {texts(r.gamma_violations)},
                        {{"threshold", gamma0_text}, {"holds", holds}, {"worst", r.worst_gamma},
                         {"worst_triangle", r.worst_gamma_triangle}, {"violations", witnesses_json(r.gamma_violations)}}});
  }
  return v;
}

std::string full_text(const CertifyVerdict& v, const std::string& input) {
  std::ostringstream o;
  o << input << ": " << v.vertices << " vertices, " << v.triangles << " triangles\n";
  for (const CheckReport& c : v.checks) {
    o << "  " << c.title << ": " << verdict(c.holds) << c.detail << "\n";
    for (const auto& lines : c.witnesses) {
      for (std::size_t i = 0; i < lines.size() && i < 3; ++i) o << "    " << lines[i] << "\n";
      if (lines.size() > 3) o << "    … and " << lines.size() - 3 << " more\n";
    }
  }
  o << (v.holds ? "certified\n" : "not certified\n");
  return o.str();
}

std::string one_line(const CertifyVerdict& v) {
  std::string s = "certify (exact): ";
  for (std::size_t i = 0; i < v.checks.size(); ++i)
    s += (i ? ", " : "") + v.checks[i].short_title + " " + verdict(v.checks[i].holds) + v.checks[i].short_detail;
  return s + ": " + (v.holds ? "certified" : "NOT certified") + "\n";
}

Json to_json(const CertifyVerdict& v) {
  Json j{{"holds", v.holds}, {"vertices", v.vertices}, {"triangles", v.triangles}};
  for (const CheckReport& c : v.checks) j[c.key] = c.json;
  return j;
}

}  // namespace anisocert::cli
