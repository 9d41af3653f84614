#pragma once
// The certifier's verdict as one report, built once from oracle::CertifyReport and rendered three
// ways: the full text of `anisocert certify`, its --json file (docs/cli.md documents every field),
// and the demo's one line. Also what the API's Certificate renders (api/anisocert.hpp). Every
// rendering is bounded by the report's own bound: per list, the exact count and the witnesses the
// certifier described (CertifyOptions::described_witnesses; the text shows three of them).
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/certify/mesh_certifier3.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace anisocert::io {

using ReportJson = nlohmann::ordered_json;

// The first lines of a list of witnesses, as the full text shows them, and how many there are.
struct WitnessLines {
  std::vector<std::string> first;   // at most three
  std::size_t count = 0;
};

// One check that ran: its JSON key and object (without its lists of witnesses, which write_json
// streams from the report itself: a bad mesh's witnesses are not copied), its title in the full text and
// in the one line, the verdict (or none: a measurement), what follows it in each (" (…)"), and the
// first lines of its lists of witnesses.
struct CheckReport {
  std::string key, title, short_title;
  bool holds = true;
  bool is_verdict = true;   // false: statistics only, no bound was given
  std::string detail, short_detail;
  std::vector<WitnessLines> witnesses;
  ReportJson json;
};

struct CertifyVerdict {
  int dimension = 2;                       // 3: a tetrahedral mesh (`triangles` then counts tetrahedra)
  std::size_t vertices = 0, triangles = 0;
  std::size_t described_witnesses = oracle::default_described_witnesses;   // per list (oracle::all_witnesses: all)
  bool has_metrics = true;
  std::string metric_source;   // where the metrics came from (a file, "--field shock"); "" when unknown
  bool holds = false;
  std::vector<CheckReport> checks;
};

// The bounds as the user gave them (shown in titles and JSON); empty when not given.
struct BoundTexts {
  std::string rho0, gamma0, length_lo, length_hi, min_quality, min_angle;
};

CertifyVerdict certify_verdict(const oracle::CertifyReport& r, const oracle::CertifyOptions& o,
                               const geometry::Mesh<Rational>& mesh, const BoundTexts& bounds);
// The same for a tetrahedral mesh (issue 39).
CertifyVerdict certify_verdict(const oracle::Certify3Report& r, const oracle::Certify3Options& o,
                               const geometry::Mesh3<Rational>& mesh, const BoundTexts& bounds);

// The certificate of a 3D star refiner's run on its own mesh (the rationals its doubles are):
// valid, locally uniform, ρ₀ and γ₀ (the run's parameters, their texts as printed), the metric
// measures without bounds; metric_source names the field ("--field NAME"). `anisocert refine` and
// the Python module's refine give the same report.
struct RunCertificate3 {
  oracle::Certify3Report report;
  CertifyVerdict verdict;
};
RunCertificate3 certify_run3(const geometry::Mesh3<Rational>& mesh, double rho0, double gamma0, int threads, const std::string& metric_source);

std::string full_text(const CertifyVerdict& v, const std::string& input);
std::string one_line(const CertifyVerdict& v);
// The --json report, written as it goes (a list of a million witnesses is never one JSON value in
// memory), laid out as nlohmann's dump(2) with one line per witness; the report behind v gives
// the lists, each its first v.described_witnesses entries after its exact count.
void write_json(std::ostream& out, const CertifyVerdict& v, const oracle::CertifyReport& r);
void write_json(std::ostream& out, const CertifyVerdict& v, const oracle::Certify3Report& r);

}  // namespace anisocert::io
