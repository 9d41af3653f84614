#pragma once
// The certifier's verdict as one report, built once from oracle::CertifyReport and rendered three
// ways: the full text of `anisocert certify`, its --json file, and the demo's one line.
#include "cli/output.hpp"
#include "oracle/certify/mesh_certifier.hpp"

#include <string>
#include <vector>

namespace anisocert::cli {

// One check that ran: its JSON key and object, its title in the full text and in the one line,
// the verdict, what follows the verdict in each (" (…)"), and lists of witnesses (text shows
// the first three of each).
struct CheckReport {
  std::string key, title, short_title;
  bool holds = false;
  std::string detail, short_detail;
  std::vector<std::vector<std::string>> witnesses;
  Json json;
};

struct CertifyVerdict {
  std::size_t vertices = 0, triangles = 0;
  bool holds = false;
  std::vector<CheckReport> checks;
};

// rho0_text, gamma0_text: the thresholds as the user gave them (shown in titles and JSON).
CertifyVerdict certify_verdict(const oracle::CertifyReport& r, const oracle::CertifyOptions& o,
                               const geometry::Mesh<Rational>& mesh, const std::string& rho0_text,
                               const std::string& gamma0_text);

std::string full_text(const CertifyVerdict& v, const std::string& input);
std::string one_line(const CertifyVerdict& v);
Json to_json(const CertifyVerdict& v);

}  // namespace anisocert::cli
